//! The README runs: every command line in its `sh` code blocks is run, in order, in one
//! temporary folder that sees the repository's `examples/`, with the built `foldcam` first on
//! the path, and must end with the exit status the line documents — 0, or `N` for a line that
//! ends in `# exit N`. Lines are run by `sh -c`, so pipes and redirections work as in a shell.
//! Skipped, and counted: `cargo …` lines (building and testing this repository, not using the
//! program) and `foldcam serve` lines (a server runs until stopped; `tests/studio/studio_server.rs`
//! covers it).

use std::path::{Path, PathBuf};
use std::process::Command;

/// One command line of the README and the exit status it documents.
#[derive(Debug)]
struct Line {
    /// Line number in README.md, from 1.
    number: usize,
    /// The command, without its trailing `# exit N` comment.
    command: String,
    /// The documented exit status.
    status: i32,
}

/// The command lines of the `sh` blocks, and the numbers of the skipped `cargo` and
/// `foldcam serve` lines.
fn command_lines(readme: &str) -> (Vec<Line>, Vec<usize>, Vec<usize>) {
    let (mut lines, mut cargo, mut serve) = (Vec::new(), Vec::new(), Vec::new());
    let mut in_sh = false;
    for (i, raw) in readme.lines().enumerate() {
        let number = i + 1;
        let t = raw.trim();
        if let Some(lang) = t.strip_prefix("```") {
            in_sh = !in_sh && (lang == "sh" || lang == "bash");
            continue;
        }
        if !in_sh || t.is_empty() || t.starts_with('#') {
            continue;
        }
        if t.starts_with("cargo ") {
            cargo.push(number);
            continue;
        }
        if t.starts_with("foldcam serve") {
            serve.push(number);
            continue;
        }
        assert!(
            t.starts_with("foldcam "),
            "README.md:{number}: a code line that is neither foldcam nor cargo: {t}"
        );
        let (command, status) = match t.rsplit_once("# exit ") {
            Some((c, n)) => (c, n.trim().parse().expect("# exit N takes a number")),
            None => (t, 0),
        };
        lines.push(Line {
            number,
            command: command.trim().to_string(),
            status,
        });
    }
    (lines, cargo, serve)
}

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn the_readme_finds_its_command_lines() {
    let text = "```sh\nfoldcam check a.fold   # exit 1\ncargo test\n# a comment\n```\n\
                foldcam outside\n```toml\nfoldcam = 1\n```\n```sh\nfoldcam serve\nfoldcam list machines\n```\n";
    let (lines, cargo, serve) = command_lines(text);
    assert_eq!(lines.len(), 2);
    assert_eq!(
        (lines[0].command.as_str(), lines[0].status),
        ("foldcam check a.fold", 1)
    );
    assert_eq!((lines[1].number, lines[1].status), (12, 0));
    assert_eq!((cargo, serve), (vec![3], vec![11]));
}

#[test]
fn every_readme_command_runs_with_its_documented_status() {
    let readme = std::fs::read_to_string(repo().join("README.md")).expect("README.md");
    let (lines, cargo, serve) = command_lines(&readme);
    // The README has its examples: a drop here means lines stopped being recognised.
    assert!(
        lines.len() >= 40,
        "only {} command lines found",
        lines.len()
    );
    eprintln!(
        "README: {} command lines run; skipped {} cargo lines ({:?}) and {} foldcam serve \
         lines ({:?})",
        lines.len(),
        cargo.len(),
        cargo,
        serve.len(),
        serve
    );
    let dir = tempfile::tempdir().expect("temp dir");
    let d = dir.path();
    link_examples(d);
    let bin = Path::new(env!("CARGO_BIN_EXE_foldcam"))
        .parent()
        .expect("bin dir")
        .to_path_buf();
    let path = std::env::join_paths(std::iter::once(bin).chain(std::env::split_paths(
        &std::env::var_os("PATH").unwrap_or_default(),
    )))
    .expect("PATH");
    // The README tells users to run these lines in a scratch folder beside `examples/`: no
    // line may write outside it.
    assert!(readme.contains("mkdir -p try && cd try && ln -s ../examples examples`"));
    let mut failures = Vec::new();
    for line in &lines {
        if line.command.contains("../") || line.command.contains(" /") {
            failures.push(format!(
                "README.md:{}: `{}` reaches outside the scratch folder",
                line.number, line.command
            ));
        }
        let out = Command::new("sh")
            .arg("-c")
            .arg(&line.command)
            .current_dir(d)
            .env("PATH", &path)
            .output()
            .expect("sh runs");
        let status = out.status.code().unwrap_or(-1);
        if status != line.status {
            failures.push(format!(
                "README.md:{}: `{}` exited {status}, documented {}\n{}",
                line.number,
                line.command,
                line.status,
                String::from_utf8_lossy(&out.stderr)
                    .lines()
                    .last()
                    .unwrap_or("")
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Makes the repository's `examples/` visible in `dir` (a symbolic link where the system has
/// them, else a copy).
fn link_examples(dir: &Path) {
    let examples = repo().join("examples");
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink(&examples, dir.join("examples")).expect("link examples");
    }
    #[cfg(not(unix))]
    {
        copy_dir(&examples, &dir.join("examples"));
    }
}

#[cfg(not(unix))]
fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).expect("mkdir");
    for entry in std::fs::read_dir(from).expect("read dir").flatten() {
        let p = entry.path();
        if p.is_dir() {
            copy_dir(&p, &to.join(entry.file_name()));
        } else {
            std::fs::copy(&p, to.join(entry.file_name())).expect("copy");
        }
    }
}
