//! What measuring a body gives: its [`Measurements`] (every [`Measure`], read by name in
//! [`Measure::ALL`] order), one value with what a reader needs to show it ([`Reading`]), and a
//! girth's tape as a 3-D polyline ([`TapePath`]). [`super::body::BodyMeasurer`] makes them.

use super::definitions::{Kind, Measure};
use serde::ser::{Serialize, SerializeMap, Serializer};

/// Every measurement of one body (`None`: a girth whose plane found no section), metres, m³, m².
#[derive(Debug, Clone, PartialEq)]
pub struct Measurements {
    pub values: [Option<f64>; Measure::ALL.len()],
}

impl Measurements {
    pub fn get(&self, m: Measure) -> Option<f64> {
        self.values[m.index()]
    }

    /// Each value with its name, label and kind, in [`Measure::ALL`] order (what a table shows).
    pub fn readings(&self) -> Vec<Reading> {
        Measure::ALL
            .into_iter()
            .map(|m| {
                let d = m.definition();
                Reading {
                    name: d.name,
                    label: d.label,
                    kind: d.kind,
                    value: self.get(m),
                }
            })
            .collect()
    }
}

/// One measurement's value with what a reader needs to show it.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Reading {
    pub name: &'static str,
    pub label: &'static str,
    pub kind: Kind,
    pub value: Option<f64>,
}

impl Serialize for Measurements {
    /// `{name: value | null}` in [`Measure::ALL`] order.
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(Some(self.values.len()))?;
        for m in Measure::ALL {
            map.serialize_entry(m.definition().name, &self.get(m))?;
        }
        map.end()
    }
}

/// A girth's tape as a closed 3-D polyline (for figures and overlays).
#[derive(Debug, Clone, PartialEq)]
pub struct TapePath {
    pub measure: Measure,
    pub points: Vec<[f64; 3]>,
}
