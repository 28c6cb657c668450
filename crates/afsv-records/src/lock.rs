//! One run at a time on a checkpoint or an ask/tell state file: the run holds an exclusive
//! OS lock (`flock`) on `FILE.lock` beside it while it reads, advances and writes the file.
//! A second run on the same file is refused at once, with the first run's pid and host, and
//! whether that pid is running. The OS releases the lock when the holding process ends,
//! however it ends (a killed run leaves no stale lock behind); a run that ends normally
//! also removes the lock file.
//!
//! The lock file holds `afsv run lock`, then `pid`, `host` and `command` lines. An existing
//! `FILE.lock` that does not start so is not afsv's: it is refused, never overwritten.

use std::fs::{File, OpenOptions};
use std::io::{Read, Seek, Write};
use std::path::{Path, PathBuf};

/// First line of a lock file.
const MAGIC: &str = "afsv run lock";

/// The lock file of `target`: `target` with `.lock` appended (`ck.json.lock`).
pub fn lock_path(target: &Path) -> PathBuf {
    let mut s = target.as_os_str().to_owned();
    s.push(".lock");
    PathBuf::from(s)
}

/// An exclusive lock on a checkpoint or state file, held until dropped.
pub struct RunLock {
    path: PathBuf,
    file: File,
}

/// Takes the exclusive lock of `file` without waiting: `Ok(false)` when another process
/// holds it.
#[cfg(unix)]
fn try_lock(file: &File) -> std::io::Result<bool> {
    use rustix::fs::{flock, FlockOperation};
    match flock(file, FlockOperation::NonBlockingLockExclusive) {
        Ok(()) => Ok(true),
        Err(e) if e == rustix::io::Errno::WOULDBLOCK => Ok(false),
        Err(e) => Err(e.into()),
    }
}

/// Whether `path` still names the open `file` (the run that held the lock may have
/// removed its file between our open and our lock: then the lock we hold guards nothing).
#[cfg(unix)]
fn names(path: &Path, file: &File) -> bool {
    use std::os::unix::fs::MetadataExt;
    match (std::fs::metadata(path), file.metadata()) {
        (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
        _ => false,
    }
}

/// Elsewhere the standard library's lock (Rust 1.89; afsv's platforms are Unix).
#[cfg(not(unix))]
#[allow(clippy::incompatible_msrv)]
fn try_lock(file: &File) -> std::io::Result<bool> {
    match file.try_lock() {
        Ok(()) => Ok(true),
        Err(std::fs::TryLockError::WouldBlock) => Ok(false),
        Err(std::fs::TryLockError::Error(e)) => Err(e),
    }
}

/// Elsewhere an open file cannot be removed: the path names it.
#[cfg(not(unix))]
fn names(_path: &Path, _file: &File) -> bool {
    true
}

/// This machine's name (`/proc/sys/kernel/hostname`, else `HOSTNAME`), for the lock file.
fn host() -> String {
    std::fs::read_to_string("/proc/sys/kernel/hostname")
        .ok()
        .or_else(|| std::env::var("HOSTNAME").ok())
        .map(|h| h.trim().to_string())
        .filter(|h| !h.is_empty())
        .unwrap_or_else(|| "unknown".into())
}

/// The value of the `key: value` line of a lock file's text.
fn field<'a>(text: &'a str, key: &str) -> Option<&'a str> {
    text.lines()
        .find_map(|l| l.strip_prefix(key)?.strip_prefix(": "))
        .map(str::trim)
}

/// Why the lock is not ours: who holds it, from the lock file's text.
fn held_by(flag: &str, target: &Path, path: &Path, text: &str) -> String {
    let who = match (field(text, "pid"), field(text, "host")) {
        // Where /proc lists processes (Linux), say whether the pid runs here.
        (Some(pid), Some(h)) if h == host() && Path::new("/proc/self").exists() => {
            let running = Path::new("/proc").join(pid).exists();
            format!(
                "pid {pid} on this machine, {}",
                if running {
                    "running"
                } else {
                    "not visible here (another container?)"
                }
            )
        }
        (Some(pid), Some(h)) if h == host() => format!("pid {pid} on this machine"),
        (Some(pid), Some(h)) => format!("pid {pid} on host {h}"),
        _ => "a run that is starting".into(),
    };
    format!(
        "{flag} {}: another run holds it ({who}; lock {}); wait for that run to end or stop it: the lock is released when its process ends, however it ends",
        target.display(),
        path.display()
    )
}

impl RunLock {
    /// Takes the lock of `target` (named `flag` in messages) or says who holds it.
    pub fn take(flag: &str, target: &Path) -> Result<Self, String> {
        let path = lock_path(target);
        let at = |e: std::io::Error| {
            format!(
                "{flag} {}: cannot lock it through {}: {e}",
                target.display(),
                path.display()
            )
        };
        // A few rounds: each retry means a holder removed its lock file as we opened it.
        for _ in 0..8 {
            let mut file = OpenOptions::new()
                .read(true)
                .write(true)
                .create(true)
                .truncate(false)
                .open(&path)
                .map_err(at)?;
            let mut text = String::new();
            let readable = (&file).take(4096).read_to_string(&mut text).is_ok();
            // (A holder may be half-way through writing its lines: a prefix of ours is ours.)
            if !readable || !(text.starts_with(MAGIC) || MAGIC.starts_with(&text)) {
                return Err(format!(
                    "{flag} {}: {} exists and was not written by afsv (afsv keeps the run lock there); move it away",
                    target.display(),
                    path.display()
                ));
            }
            if !try_lock(&file).map_err(at)? {
                return Err(held_by(flag, target, &path, &text));
            }
            if !names(&path, &file) {
                continue;
            }
            let command: Vec<String> = std::env::args().take(3).collect();
            file.set_len(0).map_err(at)?;
            file.rewind().map_err(at)?;
            write!(
                file,
                "{MAGIC}\npid: {}\nhost: {}\ncommand: {}\n",
                std::process::id(),
                host(),
                command.join(" ")
            )
            .and_then(|()| file.flush())
            .map_err(at)?;
            return Ok(Self { path, file });
        }
        Err(at(std::io::Error::other(
            "the lock file keeps being replaced",
        )))
    }
}

/// Take the lock of the state file `target` when an option (`flag`) gave one, then read the
/// file under it ([`crate::stored::read_stored`]): the lock, held until it is dropped, and
/// the file's text (`None` when it does not exist yet); neither without a file.
pub fn take_and_read(
    flag: &str,
    target: Option<&Path>,
) -> Result<(Option<RunLock>, Option<String>), String> {
    let Some(path) = target else {
        return Ok((None, None));
    };
    let lock = RunLock::take(flag, path)?;
    Ok((Some(lock), crate::stored::read_stored(flag, path)?))
}

impl Drop for RunLock {
    /// Removes the lock file (while still holding the lock, so that no other run can have
    /// taken it), then releases the lock by closing it.
    fn drop(&mut self) {
        if names(&self.path, &self.file) {
            let _ = std::fs::remove_file(&self.path);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("afsv-lock-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn a_second_lock_is_refused_with_the_holder_and_freed_on_drop() {
        let ck = dir("second").join("ck.json");
        let first = RunLock::take("--checkpoint", &ck).unwrap();
        let text = std::fs::read_to_string(lock_path(&ck)).unwrap();
        assert!(text.starts_with(MAGIC), "{text}");
        assert_eq!(field(&text, "pid"), Some(&*std::process::id().to_string()));
        // flock locks belong to the open file: a second open in this process conflicts.
        let e = RunLock::take("--checkpoint", &ck).err().unwrap();
        assert!(
            e.contains("another run holds it")
                && e.contains(&format!("pid {}", std::process::id()))
                && e.contains("running")
                && e.contains("ck.json.lock"),
            "{e}"
        );
        drop(first);
        assert!(!lock_path(&ck).exists(), "the lock file was left behind");
        drop(RunLock::take("--checkpoint", &ck).unwrap());
    }

    #[test]
    fn a_foreign_lock_file_is_refused_and_kept() {
        let ck = dir("foreign").join("ck.json");
        std::fs::write(lock_path(&ck), "my notes\n").unwrap();
        let e = RunLock::take("--checkpoint", &ck).err().unwrap();
        assert!(e.contains("not written by afsv"), "{e}");
        assert_eq!(
            std::fs::read_to_string(lock_path(&ck)).unwrap(),
            "my notes\n"
        );
    }
}
