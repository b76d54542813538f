//! Writing a file gloss was asked to write (`gloss render -o`, the demo's
//! "save as", `gloss plan --dot`) without harming any other file.
//!
//! The bytes are made in memory first, so a failure never leaves half a
//! file. A regular file (or a path where nothing is yet) gets them through
//! a temporary file that the `tempfile` crate creates exclusively (O_EXCL:
//! it never opens what is already there, a symbolic link included) under
//! a random name in the output's own folder, then renames over the output;
//! if anything fails, only that temporary file is removed. A character
//! device (`-o /dev/null`, a terminal) and a FIFO with a reader
//! (`-o >(display)`) are written through, never replaced; a directory, a
//! block device, a socket, a FIFO nobody reads and a link to nothing are
//! refused.

use anyhow::{Context as _, Result, anyhow, bail};
use std::io::Write as _;
use std::path::{Path, PathBuf};

/// Write `bytes` to `dest` as described above. Errors start with "cannot
/// write DEST".
pub fn write_file(dest: &Path, bytes: &[u8]) -> Result<()> {
    let cannot = || format!("cannot write {}", dest.display());
    match target(dest).with_context(cannot)? {
        Target::Absent => replace(dest, bytes, None).with_context(cannot),
        Target::Regular(real, perms) => replace(&real, bytes, Some(perms)).with_context(cannot),
        Target::Through => write_through(dest, bytes).with_context(cannot),
    }
}

/// What is at the output's path.
enum Target {
    /// Nothing: the file is made.
    Absent,
    /// A regular file, at this path once symbolic links are followed, with
    /// its permissions (the new file keeps them).
    Regular(PathBuf, std::fs::Permissions),
    /// A character device or a FIFO: written through, never replaced.
    Through,
}

fn target(dest: &Path) -> Result<Target> {
    let own = match std::fs::symlink_metadata(dest) {
        Ok(m) => m,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Target::Absent),
        Err(e) => return Err(e.into()),
    };
    let (meta, link) = if own.file_type().is_symlink() {
        let to = std::fs::read_link(dest)?;
        match std::fs::metadata(dest) {
            Ok(m) => (m, Some(to)),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => bail!(
                "it is a symbolic link to {}, which does not exist (gloss makes no file through a link)",
                to.display()
            ),
            Err(e) => return Err(e.into()),
        }
    } else {
        (own, None)
    };
    let t = meta.file_type();
    if t.is_file() {
        let real = match link {
            Some(_) => std::fs::canonicalize(dest)?,
            None => dest.to_path_buf(),
        };
        return Ok(Target::Regular(real, meta.permissions()));
    }
    if t.is_dir() {
        bail!("it is a directory");
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt as _;
        if t.is_char_device() || t.is_fifo() {
            return Ok(Target::Through);
        }
        if t.is_block_device() {
            bail!(
                "it is a block device; gloss writes only to a regular file, a FIFO or a character device"
            );
        }
        if t.is_socket() {
            bail!(
                "it is a socket; gloss writes only to a regular file, a FIFO or a character device"
            );
        }
    }
    bail!("it is not a regular file")
}

/// The bytes into a new temporary file beside `dest`, renamed over it.
/// `perms`: those of the file replaced; a new file gets the usual ones
/// (0666 less the umask).
fn replace(dest: &Path, bytes: &[u8], perms: Option<std::fs::Permissions>) -> Result<()> {
    let dir = match dest.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let name = dest
        .file_name()
        .ok_or_else(|| anyhow!("it names no file"))?
        .to_string_lossy();
    let prefix = format!(".{name}.");
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(".tmp");
    #[cfg(unix)]
    let new_perms = {
        use std::os::unix::fs::PermissionsExt as _;
        std::fs::Permissions::from_mode(0o666)
    };
    #[cfg(unix)]
    builder.permissions(new_perms);
    let mut tmp = builder.tempfile_in(dir)?;
    tmp.write_all(bytes)?;
    tmp.flush()?;
    // On failure the PersistError holds the temporary file; dropping it
    // removes that file, which gloss made, and nothing else.
    match perms {
        Some(p) => {
            tmp.as_file().set_permissions(p)?;
            tmp.persist(dest).map(drop).map_err(|e| e.error)?;
        }
        // Nothing was there: never replace what appeared meanwhile.
        None => tmp.persist_noclobber(dest).map(drop).map_err(|e| e.error)?,
    }
    Ok(())
}

/// Write into a character device or a FIFO as it is. A FIFO is opened
/// without blocking first: with no reader that fails at once (ENXIO)
/// instead of waiting for one for ever.
fn write_through(dest: &Path, bytes: &[u8]) -> Result<()> {
    let mut options = std::fs::OpenOptions::new();
    options.write(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt as _;
        options.custom_flags(libc::O_NONBLOCK | libc::O_NOCTTY);
    }
    let mut file = match options.open(dest) {
        Ok(f) => f,
        #[cfg(unix)]
        Err(e) if e.raw_os_error() == Some(libc::ENXIO) => {
            bail!("it is a FIFO (named pipe) that nothing reads")
        }
        Err(e) => return Err(e.into()),
    };
    #[cfg(unix)]
    {
        use std::os::fd::AsRawFd as _;
        let fd = file.as_raw_fd();
        // SAFETY: fcntl on a file descriptor this function owns.
        let cleared = unsafe {
            let flags = libc::fcntl(fd, libc::F_GETFL);
            flags >= 0 && libc::fcntl(fd, libc::F_SETFL, flags & !libc::O_NONBLOCK) == 0
        };
        if !cleared {
            return Err(std::io::Error::last_os_error().into());
        }
    }
    file.write_all(bytes)?;
    file.flush()?;
    Ok(())
}
