//! MakeHuman's macro modifiers as target weights.
//!
//! Each macro variable is a value in `[0, 1]` that is split into weights of its categories by
//! piecewise-linear interpolation between anchor values (MakeHuman's documented modifier
//! semantics, re-implemented here from the description, not from its code):
//!
//! * gender `g`: female `1 − g`, male `g`;
//! * age `a`: anchors baby (1 year, `a = 0`), child (10 years, `a = 0.1875`), young (25 years,
//!   `a = 0.5`), old (90 years, `a = 1`); years ↔ value is linear on each side of 25;
//! * muscle, weight `m`: min `max(0, 1 − 2m)`, average `1 − |2m − 1|`, max `max(0, 2m − 1)`;
//! * height, proportions `h`: the average category has no target, min/uncommon `max(0, 1 − 2h)`,
//!   max/ideal `max(0, 2h − 1)`;
//! * ethnicity: African, Asian, Caucasian weights that sum to 1.
//!
//! A macro target's weight is the product of the weights of the categories in its name, e.g.
//! `universal-female-young-averagemuscle-maxweight` = female · young · avg-muscle · max-weight,
//! `height/male-old-minmuscle-averageweight-maxheight` = male · old · min-muscle · avg-weight · max-height.

/// Values of MakeHuman's macro variables (all in `[0, 1]` except `age_years`).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct MacroParams {
    /// 0 = female, 1 = male.
    pub gender: f64,
    /// Age in years (MakeHuman's range is 1–90).
    pub age_years: f64,
    /// 0 = least, 0.5 = average, 1 = most muscular.
    pub muscle: f64,
    /// 0 = thinnest, 0.5 = average, 1 = heaviest.
    pub weight: f64,
    /// 0 = shortest, 0.5 = average, 1 = tallest.
    pub height: f64,
    /// 0 = uncommon, 0.5 = regular, 1 = ideal proportions.
    pub proportions: f64,
    /// Ethnic mix: African, Asian, Caucasian (sum 1).
    pub ethnic: [f64; 3],
}

impl Default for MacroParams {
    /// MakeHuman's default human: neutral gender, 25 years, everything average, equal ethnic mix.
    fn default() -> Self {
        Self {
            gender: 0.5,
            age_years: 25.0,
            muscle: 0.5,
            weight: 0.5,
            height: 0.5,
            proportions: 0.5,
            ethnic: [1.0 / 3.0; 3],
        }
    }
}

/// MakeHuman's age value for an age in years (1 → 0, 25 → 0.5, 90 → 1).
pub fn age_value(years: f64) -> f64 {
    let v = if years < 25.0 {
        (years - 1.0) / 48.0
    } else {
        0.5 + (years - 25.0) / 130.0
    };
    v.clamp(0.0, 1.0)
}

const GENDERS: [&str; 2] = ["female", "male"];
const AGES: [&str; 4] = ["baby", "child", "young", "old"];
const LEVELS: [&str; 3] = ["min", "average", "max"];
const ETHNIC: [&str; 3] = ["african", "asian", "caucasian"];

fn gender_weights(g: f64) -> [f64; 2] {
    let g = g.clamp(0.0, 1.0);
    [1.0 - g, g]
}

fn age_weights(years: f64) -> [f64; 4] {
    let a = age_value(years);
    let (child_at, young_at) = (0.1875, 0.5);
    if a < child_at {
        let t = a / child_at;
        [1.0 - t, t, 0.0, 0.0]
    } else if a < young_at {
        let t = (a - child_at) / (young_at - child_at);
        [0.0, 1.0 - t, t, 0.0]
    } else {
        let t = (a - young_at) / (1.0 - young_at);
        [0.0, 0.0, 1.0 - t, t]
    }
}

fn level_weights(m: f64) -> [f64; 3] {
    let m = m.clamp(0.0, 1.0);
    [
        (1.0 - 2.0 * m).max(0.0),
        1.0 - (2.0 * m - 1.0).abs(),
        (2.0 * m - 1.0).max(0.0),
    ]
}

/// `[min, max]` weights of a variable whose average has no target.
fn extreme_weights(h: f64) -> [f64; 2] {
    let h = h.clamp(0.0, 1.0);
    [(1.0 - 2.0 * h).max(0.0), (2.0 * h - 1.0).max(0.0)]
}

/// Every macro target the generator may use for adults and children's blend (ages ≥ 10 years
/// blend child and young, so baby targets are never needed for ages ≥ 10).
pub fn macro_target_names() -> Vec<String> {
    let mut names = Vec::new();
    for g in GENDERS {
        for a in &AGES[1..] {
            for e in ETHNIC {
                names.push(format!("macrodetails/{e}-{g}-{a}"));
            }
            for m in LEVELS {
                for w in LEVELS {
                    names.push(format!(
                        "macrodetails/universal-{g}-{a}-{m}muscle-{w}weight"
                    ));
                    for h in ["minheight", "maxheight"] {
                        names.push(format!(
                            "macrodetails/height/{g}-{a}-{m}muscle-{w}weight-{h}"
                        ));
                    }
                    for p in ["uncommonproportions", "idealproportions"] {
                        names.push(format!(
                            "macrodetails/proportions/{g}-{a}-{m}muscle-{w}weight-{p}"
                        ));
                    }
                }
            }
        }
    }
    names
}

/// The non-zero macro target weights for `params` (target short names as in [`super::targets`]).
pub fn macro_target_weights(params: &MacroParams) -> Vec<(String, f64)> {
    let gw = gender_weights(params.gender);
    let aw = age_weights(params.age_years);
    let mw = level_weights(params.muscle);
    let ww = level_weights(params.weight);
    let hw = extreme_weights(params.height);
    let pw = extreme_weights(params.proportions);
    let esum: f64 = params.ethnic.iter().sum();
    let ew: Vec<f64> = params
        .ethnic
        .iter()
        .map(|e| if esum > 0.0 { e / esum } else { 1.0 / 3.0 })
        .collect();
    let mut out = Vec::new();
    let mut push = |name: String, w: f64| {
        if w > 1e-12 {
            out.push((name, w));
        }
    };
    for (gi, g) in GENDERS.iter().enumerate() {
        for (ai, a) in AGES.iter().enumerate() {
            let ga = gw[gi] * aw[ai];
            if ga <= 0.0 {
                continue;
            }
            for (ei, e) in ETHNIC.iter().enumerate() {
                push(format!("macrodetails/{e}-{g}-{a}"), ga * ew[ei]);
            }
            for (mi, m) in LEVELS.iter().enumerate() {
                for (wi, w) in LEVELS.iter().enumerate() {
                    let gamw = ga * mw[mi] * ww[wi];
                    push(
                        format!("macrodetails/universal-{g}-{a}-{m}muscle-{w}weight"),
                        gamw,
                    );
                    for (hi, h) in ["minheight", "maxheight"].iter().enumerate() {
                        push(
                            format!("macrodetails/height/{g}-{a}-{m}muscle-{w}weight-{h}"),
                            gamw * hw[hi],
                        );
                    }
                    for (pi, p) in ["uncommonproportions", "idealproportions"]
                        .iter()
                        .enumerate()
                    {
                        push(
                            format!("macrodetails/proportions/{g}-{a}-{m}muscle-{w}weight-{p}"),
                            gamw * pw[pi],
                        );
                    }
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn category_weights_interpolate_and_sum_to_one() {
        assert_eq!(age_weights(25.0), [0.0, 0.0, 1.0, 0.0]);
        assert_eq!(age_weights(90.0), [0.0, 0.0, 0.0, 1.0]);
        let a = age_weights(57.5);
        assert!((a[2] - 0.5).abs() < 1e-12 && (a[3] - 0.5).abs() < 1e-12);
        assert!((age_weights(10.0)[1] - 1.0).abs() < 1e-12);
        assert_eq!(level_weights(0.5), [0.0, 1.0, 0.0]);
        assert_eq!(level_weights(0.25), [0.5, 0.5, 0.0]);
        assert_eq!(extreme_weights(0.5), [0.0, 0.0]);
        assert_eq!(extreme_weights(1.0), [0.0, 1.0]);
    }

    #[test]
    fn universal_weights_sum_to_one_and_names_are_known() {
        let p = MacroParams {
            gender: 0.3,
            age_years: 40.0,
            muscle: 0.7,
            weight: 0.2,
            height: 0.9,
            proportions: 0.1,
            ethnic: [0.2, 0.3, 0.5],
        };
        let w = macro_target_weights(&p);
        let universal: f64 = w
            .iter()
            .filter(|(n, _)| n.contains("universal"))
            .map(|(_, w)| w)
            .sum();
        assert!((universal - 1.0).abs() < 1e-12);
        let ethnic: f64 = w
            .iter()
            .filter(|(n, _)| {
                ETHNIC
                    .iter()
                    .any(|e| n.starts_with(&format!("macrodetails/{e}-")))
            })
            .map(|(_, w)| w)
            .sum();
        assert!((ethnic - 1.0).abs() < 1e-12, "{ethnic}");
        let known = macro_target_names();
        assert!(
            w.iter().all(|(n, _)| known.contains(n)),
            "unknown macro target"
        );
    }
}
