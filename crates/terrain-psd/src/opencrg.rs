//! Measured roads in the ASAM OpenCRG format (regular-grid ASCII, straight reference line),
//! read as the two wheel tracks of a [`TwoTrackProfile`].
//!
//! An OpenCRG file holds a grid of elevations `z(u, v)`: rows are cross sections at
//! `u_i = u_0 + i du` along the reference line, columns are long sections at lateral offsets
//! `v_j` (positive to the left). [`read_crg`] samples the left track at `v = +b/2` and the right
//! track at `v = -b/2` (`b/2` = `half_track_m`), linearly interpolated in `v` between the two
//! neighbouring long sections:
//! `z(u_i, v) = z_{i,j} + (v - v_j) / (v_{j+1} - v_j) (z_{i,j+1} - z_{i,j})`.
//!
//! Section numbers below are those of the ASAM OpenCRG specification
//! (`documents/specification/3_Open_crg_data_format/` of `asam-ev/OpenCRG`).
//!
//! Supported:
//! - §3.2 file structure: sections `$CT` (free text, skipped), `$ROAD_CRG`, `$KD_Definition`,
//!   `$ROAD_CRG_OPTS`, `$ROAD_CRG_MODS` (keywords in any case), each ended by a line starting
//!   with `$` (a `$`, `$!...`, `$$$$...` or the next keyword); the road data is the last
//!   section: every record after the file's last `$` line.
//! - §3.3 comments: a line starting with `*` is a block comment and `!` starts an inline
//!   comment, in every section but the road data, whose records are fixed-width (§3.4.7).
//! - §3.4.2 road parameters: `REFERENCE_LINE_START_U` (default 0), `REFERENCE_LINE_END_U`
//!   (default from the rows; checked against them when given), `REFERENCE_LINE_INCREMENT`
//!   (mandatory), `LONG_SECTION_V_RIGHT` / `_LEFT` / `_INCREMENT` (defaults from the road data:
//!   given both borders the increment follows; given the increment and one border the other
//!   follows; given the increment alone the sections are centred on the reference line, as the
//!   spec's sample `handmade_straight_NaN.crg`, 3 m wide, shows).
//!   `REFERENCE_LINE_START_Z` and `REFERENCE_LINE_OFFSET_Z` are added to the elevations;
//!   positions in the plane (`_X`, `_Y`, `_OFFSET_PHI`, WGS84) do not change the tracks'
//!   heights and are read but not used.
//! - §3.4.3 data definition: `#:LRFI` (fields of 10 characters, 8 per record) and `#:LDFI`
//!   (20 characters, 4 per record); channels `D:long section at v = X,m`, `D:long section
//!   N,m` (the N-th from the right) and `D:reference line u,m`; `U:` virtual channels are
//!   ignored.
//! - §3.4.7 road data: a row longer than one record wraps to the next record; a field
//!   starting with `*` (e.g. `*missing*`) or reading `NaN` is a missing value. Missing values
//!   are accepted wherever the tracks do not need them.
//! - §3.4.5 `GRID_NAN_MODE`: the missing values between a border of a cross section and its
//!   outermost value are replaced, by that value (mode 2) or by 0 (mode 1), plus
//!   `GRID_NAN_OFFSET`; mode 0 keeps them. Without a `$ROAD_CRG_MODS` section the mode is 2,
//!   the default of the ASAM reference library (`dCrgGridNaNKeepLast`, "keep last valid
//!   boundary value"); with one, only the file's modifiers apply (§3.4.5), so mode 0 unless
//!   it says otherwise. The spec's sample `handmade_straight_NaN.crg` reads whole this way.
//! - §3.4.4 options: only those that act outside the grid or on logging and checks
//!   (`BORDER_MODE_*`, `BORDER_OFFSET_*`, `REFLINE_CONTINUATION`, `REFLINE_SEARCH_*`,
//!   `WARN_*`, `LOG_*`, `CHECK_*`); the tracks never leave the grid, so they change nothing.
//! - §3.4.5 modifiers applied: `SCALE_Z_GRID`, `SCALE_LENGTH`, `SCALE_WIDTH` (a factor of 0 is
//!   no scaling) and `REFLINE_OFFSET_Z`; accepted without effect on a straight line without
//!   slope or banking: `REFLINE_ROTCENTER_*`, `REFLINE_OFFSET_X` / `_Y` / `_PHI`,
//!   `SCALE_SLOPE`, `SCALE_BANKING`, `SCALE_CURVATURE`.
//!
//! Refused, with an error naming line and column ([`TerrainError::File`]): binary road data
//! (`#:KRBI`, `#:KDBI`, and no format line, whose §3.4.3 default is KRBI); curved reference
//! lines (a `D:reference line phi,rad` channel, or `REFERENCE_LINE_START_PHI` /
//! `REFERENCE_LINE_END_PHI` that differ); slope and banking (their channels, non-zero
//! `REFERENCE_LINE_START_S` / `_END_S` / `_START_B` / `_END_B`, an `REFERENCE_LINE_END_Z`
//! other than the start); file references (`$ROAD_CRG_FILE`); the modifiers `REFPOINT_*`
//! (re-location that sets `z` at a point); the options `BORDER_SMOOTH_UBEG` / `_UEND` when
//! non-zero; unknown sections, parameters, modifiers, options, channels and units other than
//! `m`; a missing value a track needs that no `GRID_NAN_MODE` fills (one between two values
//! of its cross section, or any when the mode is 0); track offsets outside the long
//! sections (a [`TerrainError::Parameter`] on `half_track_m`); more than
//! [`MAX_ROWS`] rows or [`MAX_VALUES`] values, checked before anything is allocated.

use crate::error::{positive, Result, TerrainError};
use crate::synth::TwoTrackProfile;

mod grid;
#[cfg(test)]
mod tests;

/// Largest number of cross sections (rows) read: 200 km at 2 cm.
pub const MAX_ROWS: usize = 10_000_000;
/// Largest number of values (rows × channels) read.
pub const MAX_VALUES: usize = 100_000_000;

/// A measured road read from an OpenCRG file: its two wheel tracks and the grid they came from.
#[derive(Debug, Clone, PartialEq)]
pub struct CrgRoad {
    /// Left (`v = +b/2`) and right (`v = -b/2`) track elevations (m), `x = u - u_0`.
    pub profile: TwoTrackProfile,
    /// `u` of the first cross section (m), after `SCALE_LENGTH`.
    pub start_u_m: f64,
    /// `v` of each long section (m, right to left), after `SCALE_WIDTH`.
    pub sections_v_m: Vec<f64>,
}

/// The text encoding of the road data (§3.4.3, §3.4.7): field width and fields per record.
#[derive(Debug, Clone, Copy)]
struct Format {
    width: usize,
    per_record: usize,
}

/// One road-data channel (§3.4.3).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Channel {
    /// `D:reference line u,m`.
    U,
    /// `D:long section at v = X,m`.
    LongAt(f64),
    /// `D:long section N,m`.
    LongIndex,
}

/// A `KEY = value` with where it stood.
#[derive(Debug, Clone)]
struct Entry {
    key: String,
    value: f64,
    line: usize,
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Section {
    Outside,
    Ct,
    Road,
    Kd,
    Opts,
    Mods,
}

/// Everything above the road data.
#[derive(Debug, Default)]
struct Header {
    road: Vec<Entry>,
    opts: Vec<Entry>,
    mods: Vec<Entry>,
    format: Option<Format>,
    channels: Vec<(Channel, usize)>,
    saw_ct: bool,
    /// The file has a `$ROAD_CRG_MODS` section (then no default modifier applies, §3.4.5).
    saw_mods: bool,
    /// Line of `$KD_Definition`.
    kd_line: Option<usize>,
}

fn at(line: usize, column: usize, message: impl Into<String>) -> TerrainError {
    TerrainError::File {
        line,
        column,
        message: message.into(),
    }
}

/// Reads the OpenCRG file `bytes` (ISO 8859-1, §3.2) and samples its two wheel tracks at
/// `v = ±half_track_m` (see the module documentation for what is supported and refused).
pub fn read_crg(bytes: &[u8], half_track_m: f64) -> Result<CrgRoad> {
    positive("half_track_m", half_track_m)?;
    let lines: Vec<&[u8]> = bytes
        .split(|&b| b == b'\n')
        .map(|l| l.strip_suffix(b"\r").unwrap_or(l))
        .collect();
    let Some(last_dollar) = lines.iter().rposition(|l| l.first() == Some(&b'$')) else {
        return Err(at(1, 1, "not an OpenCRG file: no `$` section line"));
    };
    let header = read_header(&lines[..=last_dollar])?;
    let data = &lines[last_dollar + 1..];
    let data_len = data.len() - data.iter().rev().take_while(|l| is_blank(l)).count();
    grid::grid(&header, &data[..data_len], last_dollar + 2, half_track_m)
}

fn is_blank(line: &[u8]) -> bool {
    line.iter().all(u8::is_ascii_whitespace)
}

/// The line as text without its inline comment (§3.3), trimmed.
fn text_of(line: &[u8]) -> String {
    let s: String = line.iter().map(|&b| char::from(b)).collect();
    s.split('!').next().unwrap_or("").trim().to_string()
}

fn read_header(lines: &[&[u8]]) -> Result<Header> {
    let mut h = Header::default();
    let mut section = Section::Outside;
    for (i, raw) in lines.iter().enumerate() {
        let n = i + 1;
        if raw.first() == Some(&b'$') {
            section = section_line(&text_of(raw), n)?;
            h.saw_ct |= section == Section::Ct;
            h.saw_mods |= section == Section::Mods;
            if !h.saw_ct {
                return Err(at(
                    n,
                    1,
                    "an OpenCRG file starts with its `$CT` section (§3.2)",
                ));
            }
            if section == Section::Kd {
                h.kd_line = Some(n);
            }
            continue;
        }
        if section == Section::Ct {
            continue;
        }
        let text = text_of(raw);
        if raw.first() == Some(&b'*') || text.is_empty() {
            continue;
        }
        if !h.saw_ct {
            return Err(at(
                n,
                1,
                "an OpenCRG file starts with its `$CT` section (§3.2)",
            ));
        }
        match section {
            Section::Outside => return Err(at(n, 1, "text outside a section")),
            Section::Road => h.road.push(entry(&text, n, &h.road)?),
            Section::Opts => h.opts.push(entry(&text, n, &h.opts)?),
            Section::Mods => h.mods.push(entry(&text, n, &h.mods)?),
            Section::Kd => definition(&text, n, &mut h)?,
            Section::Ct => {}
        }
    }
    Ok(h)
}

/// The section a `$` line opens, or `Outside` for a terminator (§3.2).
fn section_line(text: &str, n: usize) -> Result<Section> {
    let key = text.to_ascii_uppercase();
    Ok(match key.as_str() {
        "$CT" => Section::Ct,
        "$ROAD_CRG" => Section::Road,
        "$KD_DEFINITION" => Section::Kd,
        "$ROAD_CRG_OPTS" => Section::Opts,
        "$ROAD_CRG_MODS" => Section::Mods,
        "$ROAD_CRG_FILE" => {
            return Err(at(
                n,
                1,
                "file references ($ROAD_CRG_FILE) are not supported",
            ))
        }
        k if k
            .chars()
            .all(|c| matches!(c, '$' | '*') || c.is_whitespace()) =>
        {
            Section::Outside
        }
        _ => return Err(at(n, 1, format!("unknown section `{text}`"))),
    })
}

/// A `KEY = value` record (§3.4.2, §3.4.4, §3.4.5); a key may appear once.
fn entry(text: &str, n: usize, seen: &[Entry]) -> Result<Entry> {
    let Some((key, value)) = text.split_once('=') else {
        return Err(at(n, 1, format!("expected `KEY = value`, found `{text}`")));
    };
    let key = key.trim().to_ascii_uppercase();
    let column = text.find('=').unwrap_or(0) + 2;
    let value = match value.trim().parse::<f64>() {
        Ok(v) if v.is_finite() => v,
        _ => {
            return Err(at(
                n,
                column,
                format!("{key}: `{}` is not a finite number", value.trim()),
            ))
        }
    };
    if let Some(first) = seen.iter().find(|e| e.key == key) {
        return Err(at(
            n,
            1,
            format!("{key} is given twice (first on line {})", first.line),
        ));
    }
    Ok(Entry {
        key,
        value,
        line: n,
    })
}

/// One record of the data definition (§3.4.3).
fn definition(text: &str, n: usize, h: &mut Header) -> Result<()> {
    let lower = text.to_ascii_lowercase();
    if let Some(format) = lower.strip_prefix("#:") {
        h.format = Some(match format.trim() {
            "lrfi" => Format {
                width: 10,
                per_record: 8,
            },
            "ldfi" => Format {
                width: 20,
                per_record: 4,
            },
            "krbi" | "kdbi" => {
                return Err(at(
                    n,
                    3,
                    format!("binary road data ({text}) is not supported; use LRFI or LDFI"),
                ))
            }
            _ => return Err(at(n, 3, format!("unknown data format `{text}`"))),
        });
        return Ok(());
    }
    if lower.starts_with("u:") {
        return Ok(());
    }
    let Some(def) = lower.strip_prefix("d:") else {
        return Err(at(n, 1, format!("unknown definition `{text}`")));
    };
    let Some((name, unit)) = def.rsplit_once(',') else {
        return Err(at(
            n,
            3,
            format!("a channel is `D:name,unit`, found `{text}`"),
        ));
    };
    let name = name.split_whitespace().collect::<Vec<_>>().join(" ");
    let unit_column = text.rfind(',').unwrap_or(0) + 2;
    let channel = match name.as_str() {
        "reference line u" => Channel::U,
        "reference line phi" => {
            return Err(at(
                n,
                1,
                "a heading channel (curved reference line) is not supported",
            ))
        }
        "reference line slope" | "reference line banking" => {
            return Err(at(n, 1, format!("the channel `{name}` is not supported")))
        }
        _ => {
            if let Some(v) = name.strip_prefix("long section at v =") {
                let v = v.trim().parse::<f64>().ok().filter(|v| v.is_finite());
                Channel::LongAt(v.ok_or_else(|| at(n, 3, format!("bad v in `{text}`")))?)
            } else if let Some(k) = name.strip_prefix("long section ") {
                let count = h.channels.iter().filter(|c| c.0 != Channel::U).count();
                if k.trim().parse::<usize>().ok() != Some(count + 1) {
                    return Err(at(
                        n,
                        3,
                        format!("expected long section {}, found `{text}`", count + 1),
                    ));
                }
                Channel::LongIndex
            } else {
                return Err(at(n, 3, format!("unknown channel `{text}`")));
            }
        }
    };
    if unit.trim() != "m" {
        return Err(at(
            n,
            unit_column,
            format!("unit `{}` is not supported (m only)", unit.trim()),
        ));
    }
    if channel == Channel::U && h.channels.iter().any(|c| c.0 == Channel::U) {
        return Err(at(n, 1, "the u channel is defined twice"));
    }
    h.channels.push((channel, n));
    Ok(())
}
