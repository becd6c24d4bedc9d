//! `report-checker`: derive the numbers and figures of the report, check a report, fill the
//! template. (Arrives with the report checker.)

fn main() {}
