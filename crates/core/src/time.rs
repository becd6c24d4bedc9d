//! Calendar dates of Unix times, in UTC: what a zip entry and Moodle's worksheet write.

/// A Unix time's UTC year, month, day, hour, minute and second (Howard Hinnant's
/// `civil_from_days`).
#[must_use]
pub fn civil(unix: u64) -> (i64, i64, i64, u64, u64, u64) {
    let days = i64::try_from(unix / 86_400).unwrap_or(0);
    let secs = unix % 86_400;
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    (year, month, day, secs / 3600, secs / 60 % 60, secs % 60)
}

#[cfg(test)]
mod tests {
    use super::civil;

    #[test]
    fn days_are_the_calendars() {
        assert_eq!(civil(0), (1970, 1, 1, 0, 0, 0));
        // 2000-02-29 (a leap day of a century year) and 2026-11-29 06:53:35.
        assert_eq!(civil(951_782_400), (2000, 2, 29, 0, 0, 0));
        assert_eq!(civil(1_795_935_215), (2026, 11, 29, 6, 53, 35));
        assert_eq!(civil(951_782_400 + 86_400), (2000, 3, 1, 0, 0, 0));
    }
}
