//! The commands `cg report …` and `report-checker` share: derive, fill, check (arrives with the command line).
