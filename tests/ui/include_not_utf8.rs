// A profiles file saved in a Windows code page: the byte that is not UTF-8
// is a mistake at its line and column in the file.
stepper_profiles::include_profiles!("../../../../tests/toml_errors/not_utf8.toml");

fn main() {}
