//! The CLI's library of programs (behaviour 19.10, 19.13): `--program
//! FILE` or `--program DIR`, and the programs a run calls that sit in
//! other files of the program's own folder.

use std::collections::BTreeMap;
use std::io::{self, Write};
use std::path::{Path, PathBuf};

use super::{Fatal, read_text};

/// The most files of a folder read for a library: a folder of programs
/// is a control's memory, not a disk.
const MAX_FILES: usize = 1000;

/// The most times a run is made again to find the programs it calls in
/// the program's folder (each time finds one more program or stops).
const MAX_ROUNDS: usize = 32;

/// A file's programs, each from its header to the next (behaviour 19.10),
/// or why the file holds none the library can keep.
fn programs_of(path: &Path, name: &str) -> Result<Vec<(u32, String)>, String> {
    let file = std::fs::File::open(path).map_err(|e| format!("cannot read {name}: {e}"))?;
    let text = read_text(name, file, offsetlab::syntax::MAX_PROGRAM_BYTES).map_err(|Fatal(m)| m)?;
    let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
    let headers = offsetlab::syntax::program_headers(text);
    let Some(first) = headers.first() else {
        return Err(format!(
            "{name}: no program header; the library keeps programs by number, so each opens with its O or : line (O1002)"
        ));
    };
    if !text[..first.pos]
        .trim_matches(|c: char| c.is_whitespace() || c == '%')
        .is_empty()
    {
        return Err(format!(
            "{name}: blocks before the first program header (line {}); the library keeps whole programs, each from its O or : line",
            first.line
        ));
    }
    Ok(headers
        .iter()
        .enumerate()
        .map(|(i, h)| {
            let end = headers.get(i + 1).map_or(text.len(), |next| next.pos);
            (h.number, text[h.pos..end].to_string())
        })
        .collect())
}

/// The regular files of `dir`, by name, at most [`MAX_FILES`] (the rest
/// said on standard error), leaving out `skip` (the program itself).
fn files_of(dir: &Path, skip: Option<&Path>) -> Result<Vec<PathBuf>, String> {
    let entries =
        std::fs::read_dir(dir).map_err(|e| format!("cannot read {}: {e}", dir.display()))?;
    let skip = skip.and_then(|p| p.canonicalize().ok());
    let mut files: Vec<PathBuf> = entries
        .filter_map(|e| e.ok())
        .map(|e| e.path())
        .filter(|p| p.is_file())
        .filter(|p| skip.is_none() || p.canonicalize().ok() != skip)
        .collect();
    files.sort();
    if files.len() > MAX_FILES {
        note(&format!(
            "{}: {} files; the library reads the first {MAX_FILES} by name",
            dir.display(),
            files.len()
        ));
        files.truncate(MAX_FILES);
    }
    Ok(files)
}

fn note(msg: &str) {
    let _ = writeln!(io::stderr(), "offsetlab: note: {msg}");
}

/// Adds `programs` to the library; a number it holds already keeps its
/// first program (19.1), said with the file that lost.
fn add(library: &mut BTreeMap<u32, String>, programs: Vec<(u32, String)>, name: &str) {
    for (number, text) in programs {
        match library.entry(number) {
            std::collections::btree_map::Entry::Occupied(_) => note(&format!(
                "{name}: O{number:04} is in the library already; the first one read is kept (a control's memory holds one program per number)"
            )),
            std::collections::btree_map::Entry::Vacant(v) => {
                v.insert(text);
            }
        }
    }
}

/// `--program PATH`: a file's programs (a file without a header is
/// refused), or every file of a folder (a file without a header is left
/// out and said, never passed over in silence).
pub(super) fn library_into(path: &Path, library: &mut BTreeMap<u32, String>) -> Result<(), Fatal> {
    let name = format!("--program {}", path.display());
    if !path.is_dir() {
        let programs = programs_of(path, &name).map_err(Fatal)?;
        add(library, programs, &name);
        return Ok(());
    }
    let files = files_of(path, None).map_err(|e| Fatal(format!("{name}: {e}")))?;
    let mut read = 0;
    for file in files {
        let name = format!("--program {}", file.display());
        match programs_of(&file, &name) {
            Ok(programs) => {
                read += 1;
                add(library, programs, &name);
            }
            Err(why) => note(&format!("left out of the library: {why}")),
        }
    }
    if read == 0 {
        return Err(Fatal(format!(
            "{name}: no file in it opens with a program header (O1002), so it gives the library no program"
        )));
    }
    Ok(())
}

/// The number of the program a run's `program-not-found` names.
fn missing(run: &offsetlab::Run) -> Option<u32> {
    run.diagnostics
        .iter()
        .filter(|d| d.code == "program-not-found")
        .find_map(|d| {
            let at = d.message.find("no program O")? + "no program O".len();
            let digits: String = d.message[at..]
                .chars()
                .take_while(char::is_ascii_digit)
                .collect();
            digits.parse().ok()
        })
}

/// The programs a run of `text` calls that neither the file nor the
/// library holds, read from the other files of the program's folder
/// (behaviour 19.13: the folder stands for the control's memory), each
/// said on standard error with its file. `quiet` runs the program
/// without block reports. Nothing is read for standard input, nor when
/// the run finds every program it calls.
pub(super) fn from_folder(
    program: &str,
    text: &str,
    setup: &mut offsetlab::Setup,
    quiet: impl Fn(&str, &offsetlab::Setup) -> offsetlab::Run,
) -> Option<offsetlab::Run> {
    if program == "-" {
        return None;
    }
    let path = Path::new(program);
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let mut folder: Option<BTreeMap<u32, (PathBuf, String)>> = None;
    let mut run = quiet(text, setup);
    for _ in 0..MAX_ROUNDS {
        let Some(number) = missing(&run) else {
            break;
        };
        let index = folder.get_or_insert_with(|| index(&dir, path));
        let Some((file, program)) = index.remove(&number) else {
            break;
        };
        note(&format!(
            "O{number:04}, which the program calls, read from {} (the program's folder)",
            file.display()
        ));
        setup.programs.insert(number, program);
        // The library's own checks (behaviour 9.10: at most 1000 programs,
        // each opening with its header) hold for what the folder adds too.
        if let Some(e) = setup
            .validate()
            .into_iter()
            .find(|d| d.code == "setup-program")
        {
            setup.programs.remove(&number);
            note(&format!(
                "O{number:04} in {} is not read: {}",
                file.display(),
                e.message
            ));
            break;
        }
        run = quiet(text, setup);
    }
    Some(run)
}

/// The programs of the files of `dir` but `program`, by number: the
/// first file (by name) holding a number gives it; files without a
/// header give none.
fn index(dir: &Path, program: &Path) -> BTreeMap<u32, (PathBuf, String)> {
    let mut out = BTreeMap::new();
    let Ok(files) = files_of(dir, Some(program)) else {
        return out;
    };
    for file in files {
        let name = file.display().to_string();
        if let Ok(programs) = programs_of(&file, &name) {
            for (number, text) in programs {
                out.entry(number).or_insert_with(|| (file.clone(), text));
            }
        }
    }
    out
}
