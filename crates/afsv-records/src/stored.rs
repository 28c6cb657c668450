//! Stored state files the toolkit writes and reads back (an optimisation's checkpoint, an
//! ask/tell state): JSON the toolkit wrote ([`crate::guard::is_afsv_json`]), refused with
//! its cause when unreadable, truncated, malformed or foreign, and tied to the settings it
//! was written for.

use crate::guard::is_afsv_json;
use crate::json::message;
use serde::de::DeserializeOwned;
use serde::Serialize;
use serde_json::Value;
use std::path::Path;

/// The text of a stored afsv JSON file (a checkpoint or a state), `None` if it does not
/// exist. Unreadable, truncated, malformed or foreign files are refused with their cause
/// (a truncated file, e.g. from a full disk, is named so, with where it ends).
pub fn read_stored(flag: &str, path: &Path) -> Result<Option<String>, String> {
    let at = |what: String| format!("{flag} {}: {what}", path.display());
    let bytes = match std::fs::read(path) {
        Ok(b) => b,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(at(e.to_string())),
    };
    let text = String::from_utf8(bytes).map_err(|e| {
        at(format!(
            "not UTF-8 text (byte {}), so not a file afsv wrote",
            e.utf8_error().valid_up_to()
        ))
    })?;
    if text.trim().is_empty() {
        return Err(at(format!(
            "empty ({} bytes): not a complete file; remove it to start afresh",
            text.len()
        )));
    }
    if let Err(e) = serde_json::from_str::<Value>(&text) {
        return Err(at(if e.is_eof() {
            format!(
                "truncated: not valid JSON, it ends inside a value at line {} column {}; remove it to start afresh",
                e.line(),
                e.column()
            )
        } else {
            format!(
                "not valid JSON at line {} column {}: {}",
                e.line(),
                e.column(),
                message(&e)
            )
        }));
    }
    if !is_afsv_json(&text) {
        return Err(at("exists and was not written by afsv".into()));
    }
    Ok(Some(text))
}

/// `text` (from [`read_stored`]) as `T`, with the line and column of what does not fit.
pub fn parse_stored<T: DeserializeOwned>(flag: &str, path: &Path, text: &str) -> Result<T, String> {
    serde_json::from_str(text).map_err(|e| {
        format!(
            "{flag} {}: line {} column {}: {}",
            path.display(),
            e.line(),
            e.column(),
            message(&e)
        )
    })
}

/// `Ok` when the settings a file was `stored` with are the settings `now`; else an error
/// naming `flag` and the file.
pub fn same_settings(flag: &str, path: &Path, stored: &Value, now: &Value) -> Result<(), String> {
    if stored == now {
        Ok(())
    } else {
        Err(format!(
            "{flag} {}: written for other settings ({stored}); remove it or use the same options",
            path.display()
        ))
    }
}

/// Write `value` as JSON to `path`, whole or not at all ([`crate::atomic::write`]).
pub fn write_json<T: Serialize>(path: &Path, value: &T) -> Result<(), String> {
    let text = serde_json::to_string(value).map_err(|e| e.to_string())?;
    crate::atomic::write(path, text).map_err(|e| format!("{}: {e}", path.display()))
}

/// What an ask/tell state asks, identified: whether the state is new, its text (as stored,
/// or as the new state will be written) and that text's SHA-256, which every batch header
/// carries and every results file must carry back.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StateIdentity {
    /// The state did not exist: its file is written by [`StateIdentity::write_if_new`].
    pub created: bool,
    /// The state's text.
    pub text: String,
    /// SHA-256 of the text (lower-case hex).
    pub sha: String,
}

impl StateIdentity {
    /// The identity of `state`, read as `stored` (from [`read_stored`]; `None`: a new
    /// state, serialised as it will be written).
    pub fn of<S: Serialize>(stored: Option<String>, state: &S) -> Result<Self, String> {
        let created = stored.is_none();
        let text = match stored {
            Some(t) => t,
            None => serde_json::to_string(state).map_err(|e| e.to_string())?,
        };
        let sha = crate::provenance::sha256_hex(text.as_bytes());
        Ok(Self { created, text, sha })
    }

    /// After an `--ask`: writes a new state's file at `path`, whole or not at all (an
    /// existing one is left as it is).
    pub fn write_if_new(&self, path: &Path) -> Result<(), String> {
        if self.created {
            crate::atomic::write(path, &self.text)
                .map_err(|e| format!("{}: {e}", path.display()))?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_state_is_identified_by_the_sha_of_its_text_and_written_only_when_new() {
        let d = std::env::temp_dir().join(format!("afsv-stored-id-{}", std::process::id()));
        std::fs::create_dir_all(&d).unwrap();
        let p = d.join("state.json");
        let state = serde_json::json!({"written_by": "afsv x", "batch": 0});
        let new = StateIdentity::of(None, &state).unwrap();
        assert!(new.created);
        assert_eq!(new.text, serde_json::to_string(&state).unwrap());
        assert_eq!(new.sha, crate::provenance::sha256_hex(new.text.as_bytes()));
        assert_eq!(new.sha.len(), 64);
        new.write_if_new(&p).unwrap();
        assert_eq!(std::fs::read_to_string(&p).unwrap(), new.text);
        // a stored state keeps its own text (not a re-serialisation) and is not rewritten
        let stored = "{ \"written_by\": \"afsv x\", \"batch\": 0 }".to_string();
        let old = StateIdentity::of(Some(stored.clone()), &state).unwrap();
        assert!(!old.created);
        assert_ne!(old.sha, new.sha);
        std::fs::write(&p, "kept").unwrap();
        old.write_if_new(&p).unwrap();
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "kept");
    }

    #[test]
    fn stored_files_are_refused_with_their_cause() {
        let d = std::env::temp_dir().join(format!("afsv-stored-unit-{}", std::process::id()));
        std::fs::create_dir_all(&d).unwrap();
        let p = d.join("state.json");
        assert_eq!(read_stored("--state", &p).unwrap(), None);
        for (text, why) in [
            ("", "empty"),
            ("{\"a\": [1,", "truncated"),
            ("{\"a\": x}", "not valid JSON"),
            ("{\"a\": 1}", "not written by afsv"),
        ] {
            std::fs::write(&p, text).unwrap();
            let e = read_stored("--state", &p).unwrap_err();
            assert!(e.starts_with("--state ") && e.contains(why), "{e}");
        }
        let ours =
            serde_json::json!({"sign_convention": "afsv-v1", "written_by": "afsv x", "n": 1});
        write_json(&p, &ours).unwrap();
        let text = read_stored("--state", &p).unwrap().unwrap();
        let back: Value = parse_stored("--state", &p, &text).unwrap();
        assert_eq!(back, ours);
        assert!(parse_stored::<Vec<u8>>("--state", &p, &text)
            .unwrap_err()
            .contains("line 1 column"));
        same_settings("--state", &p, &back, &ours).unwrap();
        assert!(same_settings("--state", &p, &back, &Value::Null)
            .unwrap_err()
            .contains("other settings"));
    }
}
