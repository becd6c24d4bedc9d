//! `cg`: the kit's command line.
fn main() {}
