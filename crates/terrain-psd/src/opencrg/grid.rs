//! The grid of an OpenCRG file and its two tracks: road parameters (§3.4.2), options
//! (§3.4.4), modifiers (§3.4.5), long sections (§3.4.3) and the fixed-width road data
//! (§3.4.7). What is applied and what is refused: the parent module's documentation.

use super::{at, Channel, CrgRoad, Entry, Format, Header, MAX_ROWS, MAX_VALUES};
use crate::error::{Result, TerrainError};
use crate::synth::TwoTrackProfile;

fn find<'a>(list: &'a [Entry], key: &str) -> Option<&'a Entry> {
    list.iter().find(|e| e.key == key)
}

/// Road parameters read but without effect on a straight track's heights (§3.4.2).
const PLANAR_PARAMETERS: &[&str] = &[
    "REFERENCE_LINE_START_X",
    "REFERENCE_LINE_START_Y",
    "REFERENCE_LINE_END_X",
    "REFERENCE_LINE_END_Y",
    "REFERENCE_LINE_OFFSET_X",
    "REFERENCE_LINE_OFFSET_Y",
    "REFERENCE_LINE_OFFSET_PHI",
    "REFERENCE_LINE_START_LON",
    "REFERENCE_LINE_START_LAT",
    "REFERENCE_LINE_END_LON",
    "REFERENCE_LINE_END_LAT",
    "REFERENCE_LINE_START_ALT",
    "REFERENCE_LINE_END_ALT",
];

/// Road parameters this reader uses or checks (§3.4.2).
const USED_PARAMETERS: &[&str] = &[
    "REFERENCE_LINE_START_U",
    "REFERENCE_LINE_END_U",
    "REFERENCE_LINE_INCREMENT",
    "LONG_SECTION_V_RIGHT",
    "LONG_SECTION_V_LEFT",
    "LONG_SECTION_V_INCREMENT",
    "REFERENCE_LINE_START_Z",
    "REFERENCE_LINE_END_Z",
    "REFERENCE_LINE_OFFSET_Z",
    "REFERENCE_LINE_START_PHI",
    "REFERENCE_LINE_END_PHI",
    "REFERENCE_LINE_START_S",
    "REFERENCE_LINE_END_S",
    "REFERENCE_LINE_START_B",
    "REFERENCE_LINE_END_B",
];

/// Elevation offset (m) of the straight, level reference line; refuses slope, banking and a
/// heading that turns (§3.4.2).
fn reference_line(road: &[Entry]) -> Result<f64> {
    for e in road {
        let k = e.key.as_str();
        if !USED_PARAMETERS.contains(&k) && !PLANAR_PARAMETERS.contains(&k) {
            return Err(at(e.line, 1, format!("unknown road parameter {k}")));
        }
        if (k.ends_with("_S") || k.ends_with("_B")) && e.value != 0.0 {
            return Err(at(
                e.line,
                1,
                format!("{k} = {}: slope and banking are not supported", e.value),
            ));
        }
    }
    let start_z = find(road, "REFERENCE_LINE_START_Z").map_or(0.0, |e| e.value);
    if let Some(end) = find(road, "REFERENCE_LINE_END_Z").filter(|e| e.value != start_z) {
        return Err(at(
            end.line,
            1,
            "REFERENCE_LINE_END_Z differs from the start: a slope, not supported",
        ));
    }
    let phi = (
        find(road, "REFERENCE_LINE_START_PHI"),
        find(road, "REFERENCE_LINE_END_PHI"),
    );
    if let (Some(a), Some(b)) = phi {
        if a.value != b.value {
            let curved =
                "REFERENCE_LINE_END_PHI differs from the start: a curved line, not supported";
            return Err(at(b.line, 1, curved));
        }
    }
    Ok(start_z + find(road, "REFERENCE_LINE_OFFSET_Z").map_or(0.0, |e| e.value))
}

/// Refuses the options that would change heights inside the grid (§3.4.4).
fn check_options(opts: &[Entry]) -> Result<()> {
    for e in opts {
        let k = e.key.as_str();
        let outside_or_logging = matches!(
            k,
            "BORDER_MODE_U"
                | "BORDER_MODE_V"
                | "BORDER_OFFSET_U"
                | "BORDER_OFFSET_V"
                | "REFLINE_CONTINUATION"
        ) || ["REFLINE_SEARCH_", "WARN_", "LOG_", "CHECK_"]
            .iter()
            .any(|p| k.starts_with(p));
        let smoothing = matches!(k, "BORDER_SMOOTH_UBEG" | "BORDER_SMOOTH_UEND");
        if smoothing && e.value != 0.0 {
            return Err(at(
                e.line,
                1,
                format!("the option {k} (border smoothing) is not supported"),
            ));
        }
        if !outside_or_logging && !smoothing {
            return Err(at(e.line, 1, format!("unknown option {k}")));
        }
    }
    Ok(())
}

/// The modifiers applied (§3.4.5): scales of `z`, `u`, `v`, an offset of `z`, and the
/// replacement of missing values at the borders of each cross section.
struct Modifiers {
    scale_z: f64,
    scale_u: f64,
    scale_v: f64,
    offset_z: f64,
    /// `GRID_NAN_MODE`: 0 keep, 1 zero, 2 the last valid value towards the border.
    nan_mode: u8,
    nan_offset: f64,
}

/// Without a `$ROAD_CRG_MODS` section the reader's default modifier applies: `GRID_NAN_MODE
/// = 2`, the default of the ASAM reference library (`dCrgGridNaNKeepLast`); with one, only
/// the file's modifiers apply (§3.4.5), so a missing `GRID_NAN_MODE` keeps missing values.
fn modifiers(mods: &[Entry], has_section: bool) -> Result<Modifiers> {
    let mut m = Modifiers {
        scale_z: 1.0,
        scale_u: 1.0,
        scale_v: 1.0,
        offset_z: 0.0,
        nan_mode: if has_section { 0 } else { 2 },
        nan_offset: 0.0,
    };
    for e in mods {
        let (k, v) = (e.key.as_str(), e.value);
        let factor = if v == 0.0 { 1.0 } else { v };
        match k {
            "SCALE_Z_GRID" => m.scale_z = factor,
            "SCALE_LENGTH" | "SCALE_WIDTH" if v < 0.0 => {
                return Err(at(e.line, 1, format!("{k} = {v} must be > 0")))
            }
            "SCALE_LENGTH" => m.scale_u = factor,
            "SCALE_WIDTH" => m.scale_v = factor,
            "REFLINE_OFFSET_Z" => m.offset_z = v,
            "GRID_NAN_MODE" => {
                m.nan_mode = match v {
                    0.0 => 0,
                    1.0 => 1,
                    2.0 => 2,
                    _ => {
                        return Err(at(
                            e.line,
                            1,
                            format!("GRID_NAN_MODE = {v} is not 0, 1 or 2"),
                        ))
                    }
                }
            }
            "GRID_NAN_OFFSET" => m.nan_offset = v,
            "REFLINE_ROTCENTER_X"
            | "REFLINE_ROTCENTER_Y"
            | "REFLINE_OFFSET_X"
            | "REFLINE_OFFSET_Y"
            | "REFLINE_OFFSET_PHI"
            | "SCALE_SLOPE"
            | "SCALE_BANKING"
            | "SCALE_CURVATURE" => {}
            _ if k.starts_with("REFPOINT_") => {
                let what = "(re-location by reference point) is not supported";
                return Err(at(e.line, 1, format!("the modifier {k} {what}")));
            }
            _ => return Err(at(e.line, 1, format!("unknown modifier {k}"))),
        }
    }
    Ok(m)
}

/// `v` of the long sections (m, right to left) from their channels and the road parameters
/// (§3.4.2 defaults, §3.4.3 channels).
fn sections(h: &Header, kd_line: usize) -> Result<Vec<f64>> {
    let long: Vec<(Channel, usize)> = h
        .channels
        .iter()
        .copied()
        .filter(|c| c.0 != Channel::U)
        .collect();
    if long.len() < 2 {
        return Err(at(
            kd_line,
            1,
            format!("{} long sections: two tracks need at least 2", long.len()),
        ));
    }
    let param = |k: &str| find(&h.road, k);
    let (right, left, inc) = (
        param("LONG_SECTION_V_RIGHT"),
        param("LONG_SECTION_V_LEFT"),
        param("LONG_SECTION_V_INCREMENT"),
    );
    let last = (long.len() - 1) as f64;
    let v: Vec<f64> = if let Some(&(_, line)) = long.iter().find(|c| c.0 == Channel::LongIndex) {
        if let Some(&(_, other)) = long.iter().find(|c| matches!(c.0, Channel::LongAt(_))) {
            return Err(at(
                line.max(other),
                1,
                "long sections by number and by v are mixed",
            ));
        }
        let (r, dv) = match (right, left, inc) {
            (Some(r), Some(l), _) => (r.value, (l.value - r.value) / last),
            (Some(r), None, Some(d)) => (r.value, d.value),
            (None, Some(l), Some(d)) => (l.value - last * d.value, d.value),
            (None, None, Some(d)) => (-0.5 * last * d.value, d.value),
            _ => {
                let need = "LONG_SECTION_V_INCREMENT or LONG_SECTION_V_RIGHT and _LEFT";
                return Err(at(
                    kd_line,
                    1,
                    format!("long sections by number need {need}"),
                ));
            }
        };
        (0..long.len()).map(|j| r + j as f64 * dv).collect()
    } else {
        long.iter()
            .map(|c| if let Channel::LongAt(v) = c.0 { v } else { 0.0 })
            .collect()
    };
    let tol = 1e-6 * (v[v.len() - 1] - v[0]).abs().max(1.0);
    for (j, w) in v.windows(2).enumerate() {
        if w[1] <= w[0] {
            return Err(at(
                long[j + 1].1,
                1,
                format!(
                    "long sections must go right to left (v increasing): {} after {}",
                    w[1], w[0]
                ),
            ));
        }
        if let Some(d) = inc.filter(|d| (w[1] - w[0] - d.value).abs() > tol) {
            return Err(at(
                d.line,
                1,
                format!(
                    "LONG_SECTION_V_INCREMENT = {} but sections {} and {} are {} m apart",
                    d.value,
                    j + 1,
                    j + 2,
                    w[1] - w[0]
                ),
            ));
        }
    }
    for (border, value) in [(right, v[0]), (left, v[v.len() - 1])] {
        if let Some(b) = border.filter(|b| (b.value - value).abs() > tol) {
            return Err(at(
                b.line,
                1,
                format!(
                    "{} = {} but the outer long section is at v = {value}",
                    b.key, b.value
                ),
            ));
        }
    }
    Ok(v)
}

/// Weights `(channel, w)` interpolating linearly in `v` to `v_q` between neighbouring long
/// sections (zero weights dropped).
fn weights(v: &[f64], channels: &[usize], v_q: f64) -> Result<Vec<(usize, f64)>> {
    let (lo, hi) = (v[0], v[v.len() - 1]);
    if !(v_q >= lo && v_q <= hi) {
        return Err(TerrainError::Parameter {
            name: "half_track_m",
            value: v_q.abs(),
            requirement: format!(
                "the track at v = {v_q} m must lie within the long sections [{lo}, {hi}] m"
            ),
        });
    }
    let j = v.partition_point(|&x| x <= v_q).clamp(1, v.len() - 1) - 1;
    let t = (v_q - v[j]) / (v[j + 1] - v[j]);
    Ok([(channels[j], 1.0 - t), (channels[j + 1], t)]
        .into_iter()
        .filter(|p| p.1 > 0.0)
        .collect())
}

/// Reads one road-data record of fixed-width fields into `out` (§3.4.7).
fn record(line: &[u8], n: usize, format: Format, out: &mut [f64]) -> Result<()> {
    let end = line.len()
        - line
            .iter()
            .rev()
            .take_while(|b| b.is_ascii_whitespace())
            .count();
    let w = format.width;
    for (f, slot) in out.iter_mut().enumerate() {
        let a = f * w;
        if a >= end {
            return Err(at(
                n,
                end + 1,
                format!(
                    "the record has {f} fields, the row needs {} here",
                    out.len()
                ),
            ));
        }
        let field = &line[a..(a + w).min(end)];
        let text = std::str::from_utf8(field)
            .map_err(|_| at(n, a + 1, "not ASCII"))?
            .trim();
        *slot = if text.starts_with('*') {
            f64::NAN
        } else {
            match text.parse::<f64>() {
                Ok(z) if !z.is_infinite() && !text.is_empty() => z,
                _ => {
                    return Err(at(
                        n,
                        a + 1,
                        format!("`{text}` is not a number ({w}-character fields)"),
                    ))
                }
            }
        };
    }
    if end > out.len() * w {
        return Err(at(
            n,
            out.len() * w + 1,
            format!("text after the {} fields of the record", out.len()),
        ));
    }
    Ok(())
}

/// Replaces the missing values between each border of a cross section and its outermost
/// value (`GRID_NAN_MODE` 1: by 0, 2: by that value; plus `GRID_NAN_OFFSET`, §3.4.5).
/// Missing values between two values stay missing; so does a cross section without any.
fn fill_borders(values: &mut [f64], long: &[usize], m: &Modifiers) {
    if m.nan_mode == 0 {
        return;
    }
    let valid = |k: &usize| !values[long[*k]].is_nan();
    let (Some(first), Some(last)) = ((0..long.len()).find(valid), (0..long.len()).rfind(valid))
    else {
        return;
    };
    let fill = |z: f64| (if m.nan_mode == 1 { 0.0 } else { z }) + m.nan_offset;
    let (right, left) = (fill(values[long[first]]), fill(values[long[last]]));
    for &j in &long[..first] {
        values[j] = right;
    }
    for &j in &long[last + 1..] {
        values[j] = left;
    }
}

/// The two tracks at `v = ±half` of the road data `data` (its first record on line `first`).
pub(super) fn grid(h: &Header, data: &[&[u8]], first: usize, half: f64) -> Result<CrgRoad> {
    let kd_line = h
        .kd_line
        .ok_or_else(|| at(first, 1, "no $KD_Definition section before the road data"))?;
    let format = h.format.ok_or_else(|| {
        at(
            kd_line,
            1,
            "no data format (#:LRFI or #:LDFI): the default, KRBI, is binary and not supported",
        )
    })?;
    let z0 = reference_line(&h.road)?;
    check_options(&h.opts)?;
    let m = modifiers(&h.mods, h.saw_mods)?;
    let channels = h.channels.len();
    let v = sections(h, kd_line)?;
    let per_row = channels.div_ceil(format.per_record);
    if data.is_empty() {
        return Err(at(first, 1, "no road data"));
    }
    if data.len() % per_row != 0 {
        return Err(at(
            first + data.len() - 1,
            1,
            format!("the last row is incomplete: {channels} channels take {per_row} records a row"),
        ));
    }
    let rows = data.len() / per_row;
    if rows > MAX_ROWS || rows.saturating_mul(channels) > MAX_VALUES {
        let limit = format!("more than {MAX_ROWS} rows or {MAX_VALUES} values");
        return Err(at(
            first,
            1,
            format!("{rows} rows of {channels} channels: {limit}"),
        ));
    }
    let inc = find(&h.road, "REFERENCE_LINE_INCREMENT").ok_or_else(|| {
        at(
            first,
            1,
            "$ROAD_CRG must define REFERENCE_LINE_INCREMENT (§3.4.2)",
        )
    })?;
    let du = inc.value;
    if du <= 0.0 {
        return Err(at(inc.line, 1, "REFERENCE_LINE_INCREMENT must be > 0"));
    }
    let u0 = find(&h.road, "REFERENCE_LINE_START_U").map_or(0.0, |e| e.value);
    if let Some(end) = find(&h.road, "REFERENCE_LINE_END_U") {
        let expected = u0 + (rows - 1) as f64 * du;
        if (end.value - expected).abs() > 1e-6 * du {
            let rows_end = format!("{rows} rows from {u0} m at {du} m end at {expected} m");
            let given = end.value;
            return Err(at(
                end.line,
                1,
                format!("REFERENCE_LINE_END_U = {given} but {rows_end}"),
            ));
        }
    }
    let v: Vec<f64> = v.iter().map(|x| x * m.scale_v).collect();
    let long: Vec<usize> = (0..channels)
        .filter(|&j| h.channels[j].0 != Channel::U)
        .collect();
    let u_channel = h.channels.iter().position(|c| c.0 == Channel::U);
    let tracks = [weights(&v, &long, half)?, weights(&v, &long, -half)?];
    let place = |r: usize, j: usize| {
        (
            first + r * per_row + j / format.per_record,
            (j % format.per_record) * format.width + 1,
        )
    };
    let (mut x, mut left, mut right) = (
        Vec::with_capacity(rows),
        Vec::with_capacity(rows),
        Vec::with_capacity(rows),
    );
    let mut values = vec![0.0; channels];
    let mut prev_u = f64::NAN;
    for r in 0..rows {
        for (k, chunk) in values.chunks_mut(format.per_record).enumerate() {
            record(
                data[r * per_row + k],
                first + r * per_row + k,
                format,
                chunk,
            )?;
        }
        fill_borders(&mut values, &long, &m);
        let u = match u_channel {
            Some(j) => {
                let u = values[j];
                let (line, column) = place(r, j);
                if u.is_nan() {
                    return Err(at(line, column, "missing value in the u channel"));
                }
                if r > 0 && (u - prev_u - du).abs() > 1e-6 * du {
                    return Err(at(
                        line,
                        column,
                        format!("u = {u} m is not {du} m after the previous row"),
                    ));
                }
                u
            }
            None => u0 + r as f64 * du,
        };
        prev_u = u;
        x.push(u * m.scale_u);
        for (t, (w, out)) in tracks.iter().zip([&mut left, &mut right]).enumerate() {
            let mut z = 0.0;
            for &(j, wj) in w {
                if values[j].is_nan() {
                    let (line, column) = place(r, j);
                    let side = if t == 0 { "left" } else { "right" };
                    let why = if m.nan_mode == 0 {
                        "GRID_NAN_MODE = 0 keeps it"
                    } else {
                        "not at a border of its cross section, so no rule fills it"
                    };
                    let what = format!("missing value the {side} track needs ({why})");
                    return Err(at(line, column, what));
                }
                z += wj * values[j];
            }
            out.push(z * m.scale_z + z0 + m.offset_z);
        }
    }
    let start_u_m = x[0];
    Ok(CrgRoad {
        profile: TwoTrackProfile::from_samples(&x, &left, &right)?,
        start_u_m,
        sections_v_m: v,
    })
}
