//! Landmark name normalisation: the many spellings of CAESAR names in the wild → canonical names.
//!
//! Files differ in case, punctuation and spacing (`Rt. Axilla, Ant.`, `rt_axilla_ant`,
//! `RT AXILLA ANT`), side words (`Right`, `R`, `Rt.`), hyphens (`Metacarpal-Phal.`), and `.lnd`
//! files truncate long names to a field width (`Rt. Acromio`, `Lt. Axilla, An`). A name is
//! reduced to a key (lower-case letters and digits, side word → `rt`/`lt`, a few anatomical
//! synonyms), then matched exactly, then as an unambiguous prefix of one canonical key.

use std::sync::OnceLock;

use super::caesar::CAESAR_LANDMARKS;

/// The canonical CAESAR name of `raw`, or `None` when it matches no landmark or several.
pub fn canonical_name(raw: &str) -> Option<&'static str> {
    let key = name_key(raw);
    let side_len = side_prefix_len(&key);
    if key.len() <= side_len {
        return None;
    }
    let keys = canonical_keys();
    if let Some(i) = keys.iter().position(|k| *k == key) {
        return Some(CAESAR_LANDMARKS[i].name);
    }
    // Truncated names: the key must say enough beyond its side to be meaningful.
    if key.len() - side_len < 3 {
        return None;
    }
    let mut hits = keys.iter().enumerate().filter(|(_, k)| k.starts_with(&key));
    match (hits.next(), hits.next()) {
        (Some((i, _)), None) => Some(CAESAR_LANDMARKS[i].name),
        _ => None,
    }
}

/// The 1-based `.lnd` order of a canonical name.
pub fn lnd_order(canonical: &str) -> Option<u8> {
    CAESAR_LANDMARKS
        .iter()
        .find(|l| l.name == canonical)
        .map(|l| l.lnd_order)
}

fn canonical_keys() -> &'static Vec<String> {
    static KEYS: OnceLock<Vec<String>> = OnceLock::new();
    KEYS.get_or_init(|| CAESAR_LANDMARKS.iter().map(|l| name_key(l.name)).collect())
}

fn side_prefix_len(key: &str) -> usize {
    if key.starts_with("rt") || key.starts_with("lt") {
        2
    } else {
        0
    }
}

/// Lower-case alphanumeric words of `raw` with the side and synonyms normalised, concatenated.
fn name_key(raw: &str) -> String {
    let lower = raw.to_lowercase();
    let mut words: Vec<&str> = lower
        .split(|c: char| !c.is_alphanumeric())
        .filter(|w| !w.is_empty())
        .collect();
    if let Some(first) = words.first_mut() {
        *first = match *first {
            "right" | "r" | "rt" => "rt",
            "left" | "l" | "lt" => "lt",
            other => other,
        };
    }
    let last = words.len().saturating_sub(1);
    let mut key = String::with_capacity(lower.len());
    for (i, word) in words.iter().enumerate() {
        let word = match *word {
            "posterior" => "post",
            "anterior" => "ant",
            "epicondyle" => "epicn",
            "calcaneus" => "calcaneous",
            "phalanx" | "phalangeal" => "phal",
            "1" if i == last => "i",
            "2" if i == last => "ii",
            "5" if i == last => "v",
            other => other,
        };
        key.push_str(word);
    }
    // CAESAR's `Thelion/Bustpoint` written as its second half (`Lt. Bustpoint`, `bust point`).
    if let Some(at) = key
        .find("bustpoint")
        .filter(|&at| !key[..at].ends_with("thelion"))
    {
        key.insert_str(at, "thelion");
    }
    // `RightAcromion` / `LeftGonion` written as one word.
    for (long, short) in [("right", "rt"), ("left", "lt")] {
        if key.len() > long.len() + 2 && key.starts_with(long) {
            key.replace_range(..long.len(), short);
        }
    }
    key
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::landmarks::CAESAR_LANDMARKS;

    #[test]
    fn every_canonical_name_maps_to_itself() {
        for l in &CAESAR_LANDMARKS {
            assert_eq!(canonical_name(l.name), Some(l.name));
            assert_eq!(canonical_name(&l.name.to_uppercase()), Some(l.name));
            assert_eq!(canonical_name(&format!("  {}   ", l.name)), Some(l.name));
        }
    }

    #[test]
    fn variants_in_the_wild_are_normalised() {
        let cases = [
            ("Rt. Acromio", "Rt. Acromion"),
            ("Lt. Axilla, An", "Lt. Axilla, Ant."),
            ("Lt. Axilla, Po", "Lt. Axilla, Post."),
            ("Rt. Metacarpal-Phal. II", "Rt. Metacarpal Phal. II"),
            ("Lt. Metacarpal Phal. V ", "Lt. Metacarpal Phal. V"),
            ("right_acromion", "Rt. Acromion"),
            ("LeftGonion", "Lt. Gonion"),
            ("R Tragion", "Rt. Tragion"),
            ("rt thelion", "Rt. Thelion/Bustpoint"),
            ("Lt. Bustpoint", "Lt. Thelion/Bustpoint"),
            ("Rt. Bustpoint", "Rt. Thelion/Bustpoint"),
            ("right bust point", "Rt. Thelion/Bustpoint"),
            ("Waist, Preferred, Post", "Waist, Preferred, Post."),
            ("Rt. Calcaneus, Posterior", "Rt. Calcaneous, Post."),
            (
                "Lt. Femoral Lateral Epicondyle",
                "Lt. Femoral Lateral Epicn",
            ),
            ("rt metatarsal phal 1", "Rt. Metatarsal Phal. I"),
            ("sellion", "Sellion"),
            ("10th rib midspine", "10th Rib Midspine"),
        ];
        for (raw, want) in cases {
            assert_eq!(canonical_name(raw), Some(want), "{raw}");
        }
    }

    #[test]
    fn unknown_and_ambiguous_names_are_none() {
        for raw in [
            "",
            "Rt.",
            "Nose tip",
            "Rt. Metacarpal Phal",
            "Lt. Axilla",
            "xx",
        ] {
            assert_eq!(canonical_name(raw), None, "{raw}");
        }
    }

    #[test]
    fn lnd_order_is_the_table_order() {
        assert_eq!(lnd_order("Sellion"), Some(1));
        assert_eq!(lnd_order("Crotch"), Some(73));
        assert_eq!(lnd_order("nope"), None);
    }
}
