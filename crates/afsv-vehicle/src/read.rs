//! Reading a description: TOML text to a [`VehicleDescription`] with every error on one line
//! that names the file, the line and column, and the field path (`axle[1].track_m`).
//!
//! Three passes: the head (`format`, `kind`) picks the schema; serde reads the schema with
//! the path of the failing field tracked; then the sets whose serde form lets fields default
//! (a tire, the truck) are checked for missing keys against their complete nominal form,
//! so a forgotten field is an error, never a silent nominal value.

use serde::de::DeserializeOwned;
use toml::de::{DeTable, DeValue};

use crate::error::DescriptionError;
use crate::schema::{Articulated, Head, Kind, RigidTruck, VehicleDescription, FORMAT};

/// Largest description accepted (bytes): a complete one is about 10 kB.
pub const MAX_BYTES: usize = 1 << 20;

/// Parse the description `text` read from `origin` (a file name for messages). The result
/// is read, not yet checked against the physical ranges ([`crate::resolve`]).
pub fn parse(text: &str, origin: &str) -> Result<VehicleDescription, DescriptionError> {
    if text.len() > MAX_BYTES {
        return Err(DescriptionError::TooLarge {
            origin: origin.to_string(),
            bytes: text.len(),
            limit: MAX_BYTES,
        });
    }
    let head: Head = located(text, origin)?;
    if head.format != FORMAT {
        return Err(at_path(
            text,
            origin,
            "format",
            format!(
                "`{}` is not a known format (this afsv reads `{FORMAT}`)",
                head.format
            ),
        ));
    }
    let doc = match DeTable::parse(text) {
        Ok(d) => d,
        Err(e) => return Err(from_toml(text, origin, "", &e)),
    };
    Ok(match head.kind {
        Kind::Articulated => {
            let a: Articulated = located(text, origin)?;
            for name in a.tire.keys() {
                complete(
                    text,
                    origin,
                    doc.get_ref(),
                    &format!("tire.{}", quoted_key(name)),
                    &["tire", name.as_str()],
                    &toml_table(&tire_fiala::TireParams::nominal()),
                )?;
            }
            VehicleDescription::Articulated(a)
        }
        Kind::RigidTruck => {
            let t: RigidTruck = located(text, origin)?;
            complete(
                text,
                origin,
                doc.get_ref(),
                "truck",
                &["truck"],
                &toml_table(&roll_truck::TruckParams::nominal()),
            )?;
            VehicleDescription::RigidTruck(t)
        }
    })
}

/// A TOML key as it appears in a dotted path: bare when it can be, quoted otherwise.
pub(crate) fn quoted_key(k: &str) -> String {
    if !k.is_empty()
        && k.chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
    {
        k.to_string()
    } else {
        format!("\"{k}\"")
    }
}

/// The complete serde form of a set as a TOML table (the reference of [`complete`]).
fn toml_table<T: serde::Serialize>(v: &T) -> toml::Table {
    toml::Table::try_from(v).unwrap_or_default()
}

/// Deserialize `text` as `T` with the failing field's path.
fn located<T: DeserializeOwned>(text: &str, origin: &str) -> Result<T, DescriptionError> {
    let de = toml::Deserializer::parse(text).map_err(|e| from_toml(text, origin, "", &e))?;
    serde_path_to_error::deserialize(de).map_err(|e| {
        let path = e.path().to_string();
        let path = if path == "." { String::new() } else { path };
        from_toml(text, origin, &path, e.inner())
    })
}

/// One-line error from a TOML error: its span gives line and column.
fn from_toml(text: &str, origin: &str, path: &str, e: &toml::de::Error) -> DescriptionError {
    let (line, column) = e
        .span()
        .map(|s| line_column(text, s.start))
        .unwrap_or((1, 1));
    DescriptionError::Field {
        origin: origin.to_string(),
        line,
        column,
        path: path.to_string(),
        message: e.message().trim().replace('\n', " "),
    }
}

/// 1-based line and column (in characters) of byte `offset` of `text`.
pub(crate) fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &text[..offset];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

/// An error about the field at `path`, located in `text` where the path can be found (its
/// value, or the nearest enclosing table that exists).
pub(crate) fn at_path(text: &str, origin: &str, path: &str, message: String) -> DescriptionError {
    let (line, column) = DeTable::parse(text)
        .ok()
        .and_then(|doc| locate(doc.get_ref(), path).map(|o| line_column(text, o)))
        .unwrap_or((1, 1));
    DescriptionError::Field {
        origin: origin.to_string(),
        line,
        column,
        path: path.to_string(),
        message,
    }
}

/// Byte offset of the deepest existing part of `path` (`a.b[2].c`, keys possibly quoted).
fn locate(doc: &DeTable<'_>, path: &str) -> Option<usize> {
    let mut table = doc;
    let mut found = None;
    let mut value: Option<&DeValue<'_>> = None;
    for segment in segments(path) {
        match segment {
            Segment::Key(k) => {
                if let Some(v) = value.take() {
                    match v {
                        DeValue::Table(t) => table = t,
                        _ => return found,
                    }
                }
                let (key, v) = table.iter().find(|(key, _)| key.get_ref().as_ref() == k)?;
                found = Some(v.span().start.max(key.span().start));
                value = Some(v.get_ref());
            }
            Segment::Index(i) => {
                let Some(DeValue::Array(items)) = value else {
                    return found;
                };
                let item = items.get(i)?;
                found = Some(item.span().start);
                value = Some(item.get_ref());
            }
        }
    }
    found
}

/// One step of a field path.
enum Segment<'a> {
    Key(&'a str),
    Index(usize),
}

/// Split `a."b c"[1].d` into keys and indices.
fn segments(path: &str) -> Vec<Segment<'_>> {
    let mut out = Vec::new();
    let mut rest = path;
    while !rest.is_empty() {
        rest = rest.strip_prefix('.').unwrap_or(rest);
        if let Some(r) = rest.strip_prefix('"') {
            let end = r.find('"').unwrap_or(r.len());
            out.push(Segment::Key(&r[..end]));
            rest = r.get(end + 1..).unwrap_or("");
        } else if let Some(r) = rest.strip_prefix('[') {
            let end = r.find(']').unwrap_or(r.len());
            if let Ok(i) = r[..end].parse() {
                out.push(Segment::Index(i));
            }
            rest = r.get(end + 1..).unwrap_or("");
        } else {
            let end = rest.find(['.', '[']).unwrap_or(rest.len());
            out.push(Segment::Key(&rest[..end]));
            rest = &rest[end..];
        }
    }
    out
}

/// The table under key `k` of `t`, if there is one.
fn child<'a, 'i>(t: &'a DeTable<'i>, k: &str) -> Option<&'a DeTable<'i>> {
    t.iter()
        .find(|(key, _)| key.get_ref().as_ref() == k)
        .and_then(|(_, v)| match v.get_ref() {
            DeValue::Table(t) => Some(t),
            _ => None,
        })
}

/// Every key of `reference` (recursively into tables) must be in the user's table at the
/// keys `keys` of `doc`; the first missing one is an error naming its path under `path`.
fn complete(
    text: &str,
    origin: &str,
    doc: &DeTable<'_>,
    path: &str,
    keys: &[&str],
    reference: &toml::Table,
) -> Result<(), DescriptionError> {
    let mut table = doc;
    for k in keys {
        match child(table, k) {
            Some(t) => table = t,
            None => return Ok(()),
        }
    }
    if let Some(key) = missing_key(table, reference) {
        let full = format!("{path}.{key}");
        return Err(at_path(
            text,
            origin,
            path,
            format!("missing field `{key}` (every field must be given: `{full}`)"),
        ));
    }
    Ok(())
}

/// The first key of `reference` that `table` lacks, as a dotted path (into sub-tables).
fn missing_key(table: &DeTable<'_>, reference: &toml::Table) -> Option<String> {
    for (k, v) in reference {
        let Some((_, given)) = table.iter().find(|(key, _)| key.get_ref().as_ref() == k) else {
            return Some(quoted_key(k));
        };
        if let (toml::Value::Table(r), DeValue::Table(t)) = (v, given.get_ref()) {
            if let Some(inner) = missing_key(t, r) {
                return Some(format!("{}.{inner}", quoted_key(k)));
            }
        }
    }
    None
}
