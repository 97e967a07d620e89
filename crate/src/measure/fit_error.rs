//! The fit's own error of each measurement: what a fit's value typically differs from the same
//! measurement of the body it was fitted to, even where the measurement's landmarks are right.
//! The trust rule adds it to the landmarks' error (`trust.rs`), so that a measurement the fit
//! itself cannot take within ISO 20685-1 is not shown as trusted.
//!
//! The figures are the mean absolute difference (mm) between each fit's measurement and the
//! truth's, by `measure_accuracy` (docs/measurements.md, "The fit's own error"), on the 24
//! held-out-profile subjects of the tuning seeds 2026, 101 and 202, fitted at `base` with the
//! defaults: `placed` from the fits from their true landmarks, `estimated` from the landmark-free
//! fits; for a body-defined measurement, only the fits whose support passed (`support.rs`: the
//! fits it already calls doubtful are not its own error). They are data, in `fit_error.csv` (one
//! row a measurement with an ISO 20685-1 limit, in [`Measure::ALL`] order), which
//! `measure_accuracy DIR --from both` prints; measure them again on those seeds when the
//! alignment or a measurement changes.
//! They hold for `base`; the paper's preset and `fine` are not measured.

use std::sync::OnceLock;

use serde::Serialize;

use super::definitions::Measure;

const TABLE: &str = include_str!("fit_error.csv");

/// One measurement's own error on a fit (mm).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FitError {
    /// On a fit from placed landmarks.
    pub placed_mm: f64,
    /// On a landmark-free fit (every landmark estimated).
    pub estimated_mm: f64,
}

/// Every measurement's own error, in [`Measure::ALL`] order; `None` for a measurement without
/// an ISO 20685-1 limit (volume, area).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FitErrors(pub [Option<FitError>; Measure::ALL.len()]);

impl FitErrors {
    /// The measured table (`fit_error.csv`), read once.
    pub fn measured() -> Self {
        static PARSED: OnceLock<FitErrors> = OnceLock::new();
        *PARSED.get_or_init(|| Self(parse(TABLE).expect("fit_error.csv is checked by its test")))
    }

    /// No error of the fit's own: a measurement's trust is its landmarks' alone.
    pub fn none() -> Self {
        Self([None; Measure::ALL.len()])
    }

    /// The own error of `m`, if known.
    pub fn of(&self, m: Measure) -> Option<FitError> {
        self.0[m.index()]
    }
}

/// The table's rows in [`Measure::ALL`] order; an error names the first row out of order or
/// unreadable.
fn parse(table: &str) -> Result<[Option<FitError>; Measure::ALL.len()], String> {
    let mut values = [None; Measure::ALL.len()];
    let mut rows = table.lines().skip(1).filter(|l| !l.is_empty());
    for m in Measure::ALL.into_iter().filter(|m| m.iso_class().is_some()) {
        let row = rows
            .next()
            .ok_or(format!("no row for {}", m.definition().name))?;
        let cells: Vec<&str> = row.split(',').collect();
        let [name, placed, estimated] = cells[..] else {
            return Err(format!("not three cells: {row}"));
        };
        if name != m.definition().name {
            return Err(format!("{name}, not {}", m.definition().name));
        }
        let mm = |s: &str| {
            s.parse::<f64>()
                .ok()
                .filter(|v| *v >= 0.0)
                .ok_or(format!("{name}: {s}"))
        };
        values[m.index()] = Some(FitError {
            placed_mm: mm(placed)?,
            estimated_mm: mm(estimated)?,
        });
    }
    match rows.next() {
        Some(extra) => Err(format!("a row too many: {extra}")),
        None => Ok(values),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_has_every_judged_measurement_in_order() {
        let table = FitErrors::measured();
        for m in Measure::ALL {
            let e = table.of(m);
            assert_eq!(e.is_some(), m.iso_class().is_some(), "{:?}", m);
            if let Some(e) = e {
                assert!(e.placed_mm > 0.0 && e.placed_mm < 50.0, "{:?}", m);
                assert!(e.estimated_mm > 0.0 && e.estimated_mm < 50.0, "{:?}", m);
            }
        }
        assert!(parse("measurement,placed_mm,estimated_mm\nstature,1.4,1.3\n").is_err());
        assert!(parse("measurement,placed_mm,estimated_mm\ncervicale_height,1,1\n").is_err());
    }
}
