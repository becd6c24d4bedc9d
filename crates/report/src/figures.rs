//! (arrives with the report checker)
