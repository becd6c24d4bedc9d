//! The template's values: every placeholder filled from the derived data (arrives with the command line).
