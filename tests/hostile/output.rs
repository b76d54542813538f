//! The output written safely (src/assets/write.rs): through a temporary file
//! made with O_EXCL under a random name, renamed over the output only when
//! that is a regular file or absent; a device or FIFO written through and
//! never replaced; a file gloss did not make never deleted.

use crate::{BASE, Entry, contains_all, folder, gloss_in, temp_dir, write};
use std::os::unix::fs::PermissionsExt as _;
use std::path::Path;

fn is_png_32x24(bytes: &[u8]) {
    let img = image::load_from_memory(bytes).expect("a PNG");
    assert_eq!((img.width(), img.height()), (32, 24));
}

fn mknod(path: &Path, kind: libc::mode_t, major: u32, minor: u32) -> bool {
    let c = std::ffi::CString::new(path.as_os_str().as_encoded_bytes()).unwrap();
    // SAFETY: a valid C string; mknod only makes a node.
    unsafe { libc::mknod(c.as_ptr(), kind | 0o666, libc::makedev(major, minor)) == 0 }
}

#[test]
fn links_and_files_named_like_the_temporary_file_are_left_alone() {
    let dir = temp_dir("tmp_names");
    write(&dir, "scene.toml", BASE);
    write(&dir, "secret.txt", "the user's own file");
    // A symbolic link where gloss once wrote its temporary file.
    std::os::unix::fs::symlink("secret.txt", dir.join("out.png.tmp")).unwrap();
    // The user's own file of that name beside another output.
    write(&dir, "pic.png.tmp", "mine");
    write(&dir, "out.png", "the old picture");
    for out in ["out.png", "pic.png"] {
        let run = gloss_in(
            &dir,
            &["render", "scene.toml", "-o", out, "--size", "32x24"],
            &[out],
        );
        run.succeeded();
        is_png_32x24(&std::fs::read(dir.join(out)).unwrap());
    }
    let after = folder(&dir);
    assert_eq!(
        after["secret.txt"],
        Entry::File {
            bytes: b"the user's own file".to_vec(),
            mode: after_mode(&dir, "secret.txt")
        }
    );
    assert_eq!(after["out.png.tmp"], Entry::Link("secret.txt".into()));
}

fn after_mode(dir: &Path, name: &str) -> u32 {
    use std::os::unix::fs::MetadataExt as _;
    std::fs::metadata(dir.join(name)).unwrap().mode()
}

#[test]
fn a_replaced_picture_keeps_its_permissions_and_a_link_stays_a_link() {
    let dir = temp_dir("perms_link");
    write(&dir, "scene.toml", BASE);
    std::fs::create_dir(dir.join("real")).unwrap();
    let real = write(&dir.join("real"), "pic.png", "old");
    std::fs::set_permissions(&real, std::fs::Permissions::from_mode(0o640)).unwrap();
    std::os::unix::fs::symlink("real/pic.png", dir.join("link.png")).unwrap();
    gloss_in(
        &dir,
        &["render", "scene.toml", "-o", "link.png", "--size", "32x24"],
        &[],
    )
    .succeeded();
    // The link is as it was (checked above: nothing in the folder changed);
    // the file it names holds the picture, with its own permissions.
    is_png_32x24(&std::fs::read(&real).unwrap());
    let mode = std::fs::metadata(&real).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o640);
    assert!(std::fs::read_dir(dir.join("real")).unwrap().count() == 1);
}

#[test]
fn a_dangling_link_as_output_is_refused() {
    let dir = temp_dir("dangling_out");
    write(&dir, "scene.toml", BASE);
    std::os::unix::fs::symlink("elsewhere/nothing.png", dir.join("out.png")).unwrap();
    let run = gloss_in(
        &dir,
        &["render", "scene.toml", "-o", "out.png", "--size", "32x24"],
        &[],
    );
    contains_all(
        run.failed(),
        &["cannot write out.png", "symbolic link", "does not exist"],
    );
    assert!(!dir.join("elsewhere").exists());
}

#[test]
fn a_fifo_is_written_through_and_never_replaced() {
    let dir = temp_dir("fifo_out");
    write(&dir, "scene.toml", BASE);
    let fifo = dir.join("pipe");
    assert!(mknod(&fifo, libc::S_IFIFO, 0, 0), "mkfifo");
    // Nobody reads it: refused at once, not a wait for ever.
    let run = gloss_in(
        &dir,
        &["render", "scene.toml", "-o", "pipe", "--size", "32x24"],
        &[],
    );
    contains_all(
        run.failed(),
        &["cannot write pipe", "FIFO", "nothing reads"],
    );
    // A reader: the picture goes through the pipe.
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read(fifo).unwrap())
    };
    // Wait for the reader to open its end (a writer's non-blocking open
    // fails until then).
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(20);
    loop {
        let run = crate::gloss(
            &dir,
            &["render", "scene.toml", "-o", "pipe", "--size", "32x24"],
        );
        if run.status.success() {
            break;
        }
        assert!(run.stderr.contains("nothing reads"), "{}", run.stderr);
        assert!(std::time::Instant::now() < deadline, "no reader appeared");
        std::thread::sleep(std::time::Duration::from_millis(100));
    }
    is_png_32x24(&reader.join().unwrap());
    assert!(matches!(folder(&dir)["pipe"], Entry::Special { .. }));
}

#[test]
fn a_device_is_written_through_or_refused_never_replaced() {
    let dir = temp_dir("device_out");
    write(&dir, "scene.toml", BASE);
    // A character device like /dev/null (1, 3), and a block device; making
    // them needs root: without it, /dev/null itself stands in for the first.
    let null = if mknod(&dir.join("null"), libc::S_IFCHR, 1, 3) {
        "null".to_string()
    } else {
        eprintln!("mknod refused (not root): writing through /dev/null instead");
        "/dev/null".to_string()
    };
    let before_null = std::fs::symlink_metadata(dir.join(&null)).unwrap();
    gloss_in(
        &dir,
        &["render", "scene.toml", "-o", &null, "--size", "32x24"],
        &[],
    )
    .succeeded();
    let after_null = std::fs::symlink_metadata(dir.join(&null)).unwrap();
    use std::os::unix::fs::{FileTypeExt as _, MetadataExt as _};
    assert!(after_null.file_type().is_char_device());
    assert_eq!(after_null.rdev(), before_null.rdev());
    assert_eq!(after_null.ino(), before_null.ino(), "the node was replaced");
    if mknod(&dir.join("disk"), libc::S_IFBLK, 7, 250) {
        let run = gloss_in(
            &dir,
            &["render", "scene.toml", "-o", "disk", "--size", "32x24"],
            &[],
        );
        contains_all(run.failed(), &["cannot write disk", "block device"]);
    }
}
