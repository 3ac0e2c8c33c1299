// A profiles file that is not there: the message says where it looked.
stepper_profiles::include_profiles!("no/such/profiles.toml");

fn main() {}
