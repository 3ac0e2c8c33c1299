//! Golden files of text: the bless mechanism of `stepper_profiles::golden`
//! (`UPDATE_GOLDEN=1` writes, otherwise compare), for golden files that are
//! not tables (`tests/toml_errors/`); tables use `golden::check` itself.

use std::fs;
use std::path::Path;

use profile_codegen::__private::golden::blessing;
use profile_codegen::SpecTables;
use stepper_profiles::{Figures, Spec};

/// Writes a golden file, its folder created: beside, then renamed, so that
/// tests reading the file meanwhile see the old text or the new, never half.
pub fn write(path: &Path, text: &str) {
    fs::create_dir_all(path.parent().expect("a golden directory"))
        .unwrap_or_else(|e| panic!("cannot create the folder of {}: {e}", path.display()));
    let partial = path.with_extension("partial");
    fs::write(&partial, text)
        .and_then(|()| fs::rename(&partial, path))
        .unwrap_or_else(|e| panic!("cannot write {}: {e}", path.display()));
}

/// A golden text file: with `UPDATE_GOLDEN=1` written with `actual`;
/// otherwise compared with it, a difference described as the expected and
/// the actual text.
pub fn text(path: &Path, name: &str, actual: &str) -> Result<(), String> {
    if blessing() {
        write(path, actual);
        return Ok(());
    }
    match fs::read_to_string(path) {
        Ok(expected) if expected.replace("\r\n", "\n") == actual => Ok(()),
        Ok(expected) => Err(format!(
            "--- {name}: expected ({})\n{expected}--- {name}: actual\n{actual}",
            path.display()
        )),
        Err(_) => Err(format!(
            "--- {name}: no golden file {}; actual\n{actual}",
            path.display()
        )),
    }
}

/// `spec`'s table as `Spec::table()` computes it, its periods and figures,
/// after checking that `period_table!` expanded to the same periods.
#[track_caller]
pub fn checked_periods(file: &str, spec: &Spec, from_macro: &[u16]) -> (Vec<u32>, Figures) {
    let table = spec
        .table()
        .unwrap_or_else(|e| panic!("{file}: expected a valid table, got the error {e}"));
    let from_macro: Vec<u32> = from_macro.iter().map(|&p| u32::from(p)).collect();
    let first_difference = from_macro
        .iter()
        .zip(&table.periods)
        .position(|(m, t)| m != t);
    assert!(
        from_macro.len() == table.periods.len() && first_difference.is_none(),
        "{file}: expected period_table! to equal Spec::table(); lengths {} and {}, first \
         difference at index {first_difference:?}",
        from_macro.len(),
        table.periods.len()
    );
    (table.periods, table.figures)
}
