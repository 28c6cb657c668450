//! The input files a run read, by name and SHA-256, so that a number in a report can be
//! traced to its inputs. Readers of user files call [`read_input`] (records, parameter
//! files and vehicle descriptions do); a command's outputs list [`inputs`].
//!
//! The list is process-wide and bounded ([`MAX_INPUTS`]): a long-lived library user does not
//! grow it without end, and the same file read twice is listed once.

use sha2::{Digest, Sha256};
use std::path::Path;
use std::sync::Mutex;

/// Most input files remembered per process.
pub const MAX_INPUTS: usize = 1000;

/// One input file: its path as given and the SHA-256 of the bytes read.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct InputFile {
    /// The path as the user gave it (or as a description resolved it).
    pub file: String,
    /// SHA-256 of the contents, lowercase hex.
    pub sha256: String,
}

static INPUTS: Mutex<Vec<InputFile>> = Mutex::new(Vec::new());

/// SHA-256 of `bytes` as lowercase hex.
pub fn sha256_hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// Remember that `path` was read with these contents.
pub fn note(path: &Path, contents: &[u8]) {
    let entry = InputFile {
        file: path.display().to_string(),
        sha256: sha256_hex(contents),
    };
    let mut list = INPUTS.lock().unwrap_or_else(|e| e.into_inner());
    if list.len() < MAX_INPUTS && !list.contains(&entry) {
        list.push(entry);
    }
}

/// Read the text file `path` and remember it ([`note`]).
pub fn read_input(path: &Path) -> std::io::Result<String> {
    let text = std::fs::read_to_string(path)?;
    note(path, text.as_bytes());
    Ok(text)
}

/// The input files read so far, in order.
pub fn inputs() -> Vec<InputFile> {
    INPUTS.lock().unwrap_or_else(|e| e.into_inner()).clone()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sha256_of_known_texts() {
        assert_eq!(
            sha256_hex(b""),
            "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855"
        );
        assert_eq!(
            sha256_hex(b"abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"
        );
    }

    #[test]
    fn a_file_read_is_listed_once_with_its_hash() {
        let dir = tempfile::tempdir().unwrap();
        let f = dir.path().join("in.csv");
        std::fs::write(&f, "abc").unwrap();
        assert_eq!(read_input(&f).unwrap(), "abc");
        read_input(&f).unwrap();
        let hits: Vec<InputFile> = inputs()
            .into_iter()
            .filter(|i| i.file.ends_with("in.csv"))
            .collect();
        assert_eq!(hits.len(), 1);
        assert_eq!(hits[0].sha256, sha256_hex(b"abc"));
    }
}
