//! Errors of reading and checking a vehicle description: one line each, naming the file,
//! the line and column, and the field path.

/// What is wrong with a description.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DescriptionError {
    /// The file could not be read.
    #[error("{origin}: {reason}")]
    Io {
        /// The file.
        origin: String,
        /// The operating system's reason.
        reason: String,
    },
    /// The file is larger than any description.
    #[error("{origin}: {bytes} bytes, more than the {limit} a vehicle description may have")]
    TooLarge {
        /// The file.
        origin: String,
        /// Its size.
        bytes: usize,
        /// The limit.
        limit: usize,
    },
    /// A field is malformed, missing, unknown, out of its range or inconsistent with
    /// another.
    #[error("{origin}:{line}:{column}: {}{message}", field_prefix(path))]
    Field {
        /// The file.
        origin: String,
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// The field path (`axle[1].track_m`), empty for the whole file.
        path: String,
        /// What is wrong, with the allowed range where there is one.
        message: String,
    },
}

fn field_prefix(path: &str) -> String {
    if path.is_empty() {
        String::new()
    } else {
        format!("`{path}`: ")
    }
}
