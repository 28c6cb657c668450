//! Tests of the OpenCRG reader on small hand-written files.

use super::read_crg;
use crate::error::TerrainError;

/// Three rows, three long sections given by `v`, LRFI, comments of both kinds.
const STRAIGHT: &str = "\
$CT
hand-made straight road: 3 cross sections, long sections at v = -1, 0, 1 m
$
$ROAD_CRG                        ! road parameters
REFERENCE_LINE_START_U   = 10.0
REFERENCE_LINE_END_U     = 11.0
REFERENCE_LINE_INCREMENT = 0.5   ! 3 rows
REFERENCE_LINE_START_X   = 4.0
$!********************************
$KD_Definition
#:LRFI
U:reference line u,m,0,1.0
D:long section at v = -1.0,m     ! right
D:long section at v =  0.0,m
D:long section at v =  1.0,m     ! left
$
* a block comment between sections
$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$
 0.0200000 0.0200000 0.0400000
-0.0100000 0.0000000 0.0300000
 0.0000000 0.1000000 0.2000000
";

/// The structure of the spec's sample `handmade_straight_NaN.crg`: long sections by number
/// centred on the reference line (only `LONG_SECTION_V_INCREMENT`), missing values at the
/// borders, fields that touch (`0.0000000-0.0100000`). Own numbers.
const BY_NUMBER: &str = "\
$CT
straight road 3 m wide, 4 m long, grid 1.0 m x 0.5 m, missing values at the borders
% free text in the header, even with a $ inside it
$
$ROAD_CRG
REFERENCE_LINE_INCREMENT = 1.0
LONG_SECTION_V_INCREMENT = 0.50
$
$KD_Definition
#:LRFI
D:long section 1,m
D:long section 2,m
D:long section 3,m
D:long section 4,m
D:long section 5,m
D:long section 6,m
D:long section 7,m
$
$$$$
 0.0000000 0.0000000 0.0000000 0.0000000 0.0000000 0.0000000 0.0000000
 *missing* 0.0100000 0.0200000 0.0300000 0.0400000 *missing* *missing*
 *missing* *missing* 0.0000000-0.0100000-0.0200000-0.0300000 *missing*
 0.0100000 0.0100000 0.0100000 0.0100000 0.0100000 0.0100000 0.0100000
";

fn close(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-12)
}

/// The 1-based line of `text` that contains `part`.
fn line_of(text: &str, part: &str) -> usize {
    text.lines().position(|l| l.contains(part)).expect(part) + 1
}

fn file_error(text: &str, half_track_m: f64) -> (usize, usize, String) {
    match read_crg(text.as_bytes(), half_track_m) {
        Err(TerrainError::File {
            line,
            column,
            message,
        }) => (line, column, message),
        other => panic!("expected a file error, got {other:?}"),
    }
}

#[test]
fn straight_tracks_interpolate_between_long_sections() {
    // b/2 = 0.25: left at v = 0.25 is 0.75 z(0) + 0.25 z(1); right at v = -0.25 is
    // 0.25 z(-1) + 0.75 z(0).
    let road = read_crg(STRAIGHT.as_bytes(), 0.25).unwrap();
    assert_eq!(road.start_u_m, 10.0);
    assert_eq!(road.sections_v_m, vec![-1.0, 0.0, 1.0]);
    assert_eq!(road.profile.dx_m, 0.5);
    assert!(close(&road.profile.left_m, &[0.025, 0.0075, 0.125]));
    assert!(close(&road.profile.right_m, &[0.02, -0.0025, 0.075]));
}

#[test]
fn sample_structure_centres_numbered_sections_and_skips_unneeded_gaps() {
    // 7 sections 0.5 m apart centred: v = -1.5 .. 1.5; b/2 = 0.5 hits sections 3 and 5.
    let road = read_crg(BY_NUMBER.as_bytes(), 0.5).unwrap();
    assert_eq!(
        road.sections_v_m,
        vec![-1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5]
    );
    assert_eq!(road.start_u_m, 0.0);
    assert_eq!(road.profile.dx_m, 1.0);
    assert!(close(&road.profile.left_m, &[0.0, 0.04, -0.02, 0.01]));
    assert!(close(&road.profile.right_m, &[0.0, 0.02, 0.0, 0.01]));
}

#[test]
fn missing_values_at_the_borders_are_filled_by_the_grid_nan_mode() {
    // b/2 = 0.75: left between sections 5 and 6, right between 2 and 3. Row 2 misses 6 and 7
    // (left border), row 3 misses 1 and 2 (right border) and 7.
    let road = read_crg(BY_NUMBER.as_bytes(), 0.75).unwrap();
    assert!(close(&road.profile.left_m, &[0.0, 0.04, -0.025, 0.01]));
    assert!(close(&road.profile.right_m, &[0.0, 0.015, 0.0, 0.01]));
    // Mode 1 fills with 0, plus the offset.
    let mods = "$\n$ROAD_CRG_MODS\nGRID_NAN_MODE = 1\nGRID_NAN_OFFSET = 0.1\n$\n$$$$";
    let zero = BY_NUMBER.replacen("$\n$$$$", mods, 1);
    let road = read_crg(zero.as_bytes(), 0.75).unwrap();
    assert!(close(&road.profile.left_m, &[0.0, 0.07, -0.025, 0.01]));
    assert!(close(&road.profile.right_m, &[0.0, 0.015, 0.05, 0.01]));
}

#[test]
fn a_missing_value_a_track_needs_is_refused_at_its_line_and_column() {
    // Between two values of its cross section no rule fills it.
    let inner = BY_NUMBER.replace(
        " 0.0100000 0.0100000 0.0100000 0.0100000 0.0100000",
        " 0.0100000 0.0100000 0.0100000 0.0100000 *missing*",
    );
    let (line, column, message) = file_error(&inner, 0.5);
    assert_eq!((line, column), (line_of(&inner, "0.0100000 *missing*"), 41));
    assert!(message.contains("left track"), "{message}");
    // A modifiers section without GRID_NAN_MODE, or with 0, keeps border gaps (§3.4.5).
    for mods in ["SCALE_Z_GRID = 1.0", "GRID_NAN_MODE = 0"] {
        let section = format!("$\n$ROAD_CRG_MODS\n{mods}\n$\n$$$$");
        let text = BY_NUMBER.replacen("$\n$$$$", &section, 1);
        let (line, column, message) = file_error(&text, 0.75);
        assert_eq!((line, column), (line_of(&text, " *missing* 0.0100000"), 51));
        assert!(message.contains("keeps"), "{message}");
    }
}

/// `fields` right-aligned in `width` characters, one record.
fn fixed(width: usize, fields: &[&str]) -> String {
    let mut s: String = fields.iter().map(|f| format!("{f:>width$}")).collect();
    s.push('\n');
    s
}

#[test]
fn double_format_wraps_rows_and_applies_u_channel_and_modifiers() {
    // 5 channels in LDFI (4 a record): 2 records a row. v = -2, -1, 0, 1 from the borders.
    let mut text = String::from(
        "$CT\nLDFI with a u channel\n$\n$ROAD_CRG\nREFERENCE_LINE_INCREMENT = 0.25\n\
         LONG_SECTION_V_RIGHT = -2.0\nLONG_SECTION_V_LEFT = 1.0\nREFERENCE_LINE_START_Z = 0.25\n$\n\
         $ROAD_CRG_OPTS\nBORDER_MODE_U = 1\n$\n$ROAD_CRG_MODS\nSCALE_Z_GRID = 2.0\n\
         REFLINE_OFFSET_Z = 0.25\nSCALE_LENGTH = 2.0\n$\n$KD_Definition\n#:LDFI\n\
         D:reference line u,m\nD:long section 1,m\nD:long section 2,m\nD:long section 3,m\n\
         D:long section 4,m\n$\n",
    );
    text += &fixed(20, &["5.0", "*missing*", "0.01", "0.02"]);
    text += &fixed(20, &["0.04"]);
    text += &fixed(20, &["5.25", "0.0", "-0.01", "0.0"]);
    text += &fixed(20, &["0.01"]);
    let road = read_crg(text.as_bytes(), 0.5).unwrap();
    assert_eq!(road.sections_v_m, vec![-2.0, -1.0, 0.0, 1.0]);
    assert_eq!((road.start_u_m, road.profile.dx_m), (10.0, 0.5));
    // z = 2 (mean of the two sections) + 0.25 + 0.25.
    assert!(close(&road.profile.left_m, &[0.56, 0.51]));
    assert!(close(&road.profile.right_m, &[0.53, 0.49]));
    // A u channel that does not step by the increment is refused at its field.
    let bad = text.replace(&format!("{:>20}", "5.25"), &format!("{:>20}", "5.5"));
    let (line, column, _) = file_error(&bad, 0.5);
    assert_eq!(
        (line, column),
        (line_of(&bad, &format!("{:>20}", "5.5")), 1)
    );
}

#[test]
fn binary_formats_are_refused_and_so_is_the_binary_default() {
    let krbi = BY_NUMBER.replace("#:LRFI", "#:KRBI");
    let (line, _, message) = file_error(&krbi, 0.5);
    assert_eq!(line, line_of(&krbi, "#:KRBI"));
    assert!(message.contains("binary"), "{message}");
    let none = BY_NUMBER.replace("#:LRFI\n", "");
    let (line, _, message) = file_error(&none, 0.5);
    assert_eq!(line, line_of(&none, "$KD_Definition"));
    assert!(message.contains("KRBI"), "{message}");
}

#[test]
fn offsets_outside_the_long_sections_are_refused() {
    let e = read_crg(BY_NUMBER.as_bytes(), 1.6).unwrap_err();
    assert!(
        matches!(
            e,
            TerrainError::Parameter {
                name: "half_track_m",
                ..
            }
        ),
        "{e}"
    );
    assert!(read_crg(BY_NUMBER.as_bytes(), 1.5).is_ok());
    assert!(read_crg(BY_NUMBER.as_bytes(), 0.25).is_ok());
}

#[test]
fn unsupported_content_is_refused_at_its_line() {
    let cases = [
        (
            "#:LRFI\n",
            "#:LRFI\nD:reference line phi,rad\n",
            "D:reference line phi",
        ),
        ("$\n$$$$", "$\n$ROAD_CRG_FILE\nx\n$\n$$$$", "$ROAD_CRG_FILE"),
        (
            "LONG_SECTION_V_INCREMENT = 0.50\n",
            "LONG_SECTION_V_INCREMENT = 0.50\n\
             REFERENCE_LINE_START_PHI = 0\nREFERENCE_LINE_END_PHI = 1\n",
            "REFERENCE_LINE_END_PHI",
        ),
        (
            "$\n$$$$",
            "$\n$ROAD_CRG_MODS\nREFPOINT_X = 3\n$\n$$$$",
            "REFPOINT_X",
        ),
        (
            "$\n$$$$",
            "$\n$ROAD_CRG_MODS\nGRID_NAN_MODE = 3\n$\n$$$$",
            "GRID_NAN_MODE",
        ),
        (
            "REFERENCE_LINE_INCREMENT = 1.0\n",
            "REFERENCE_LINE_INCREMENT = 1.0\nREFERENCE_LINE_START_S = 0.01\n",
            "REFERENCE_LINE_START_S",
        ),
        (
            "D:long section 7,m",
            "D:long section 7,mm",
            "D:long section 7",
        ),
        ("0.0400000 *missing*", "0.04000x0 *missing*", "0.04000x0"),
    ];
    for (from, to, at) in cases {
        assert!(BY_NUMBER.contains(from), "{from}");
        let text = BY_NUMBER.replacen(from, to, 1);
        let (line, _, message) = file_error(&text, 0.5);
        assert_eq!(line, line_of(&text, at), "{to}: {message}");
    }
}

#[test]
fn rows_must_be_complete_and_the_file_must_start_with_its_header() {
    let short = BY_NUMBER.replace("0.0100000 0.0100000\n", "0.0100000\n");
    let (line, column, _) = file_error(&short, 0.5);
    assert_eq!((line, column), (short.lines().count(), 61));
    let (line, _, _) = file_error(&BY_NUMBER.replacen("$CT\n", "", 1), 0.5);
    assert_eq!(line, 1);
}

#[test]
fn every_prefix_and_every_single_byte_change_gives_a_value_or_an_error() {
    // No panic on a truncated or corrupted file; the whole file still reads.
    // Up to the second data row a prefix holds at most one row: never a profile.
    let second_row = BY_NUMBER.find(" *missing* 0.0100000").expect("row");
    let bytes = BY_NUMBER.as_bytes();
    for k in 0..bytes.len() {
        let prefix = read_crg(&bytes[..k], 0.5);
        assert!(k > second_row || prefix.is_err(), "prefix {k}");
        for b in [b'$', b'*', b'!', b'\n', b'-', b'9', 0xE9] {
            let mut changed = bytes.to_vec();
            changed[k] = b;
            let _ = read_crg(&changed, 0.5);
        }
    }
    assert!(read_crg(bytes, 0.5).is_ok());
}
