//! Landmark readers and writers end to end on files built in the test: CAESAR `.lnd` with
//! missing landmarks, CRLF and name variants; CSV with quoted names; JSON; broken files.

use bodyspace::io::{read_landmarks, write_landmarks_csv, write_lnd, IoError};
use bodyspace::landmarks::{report, Landmark, LandmarkSet, CAESAR_LANDMARKS};
use nalgebra::Point3;

fn lnd_file() -> String {
    [
        "SUBJECT_ID = csr0042a",
        "SCAN_TYPE = standing",
        "STD_LAND = 6",
        "AUX_LAND = 0",
        "STANDARD =",
        "AUX =",
        "   1    0    1    0.000   -115.900   1019.300   1462.500 Sellion",
        "   2    0    1    0.000   -110.000    980.000   1420.000 Rt. Acromio   ",
        "   3 -999 -999 -999.000   -999.000   -999.000   -999.000 Lt. Axilla, An",
        "   4    0    1    0.000     12.500    -40.250    900.000 Rt. Metacarpal-Phal. II",
        "   5    0    1    0.000     10.000     20.000     30.000 WAIST, PREFERRED, POST.",
        "   6    2    0    1.500      1.000      2.000      3.000 Nose Tip",
        "END =",
        "trailing text the reader must ignore",
    ]
    .join("\r\n")
}

#[test]
fn lnd_with_missing_landmarks_crlf_and_name_variants() {
    let set = read_landmarks(lnd_file().as_bytes(), "csr0042a.lnd").unwrap();
    let names: Vec<&str> = set.landmarks.iter().map(|l| l.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "Sellion",
            "Rt. Acromion",
            "Rt. Metacarpal Phal. II",
            "Waist, Preferred, Post.",
            "Nose Tip"
        ]
    );
    assert_eq!(
        set.get("Sellion"),
        Some(Point3::new(-115.9, 1019.3, 1462.5))
    );
    assert_eq!(set.missing, ["Lt. Axilla, Ant."]);
    assert_eq!(set.unknown, ["Nose Tip"]);
    let r = report(&set);
    assert_eq!(
        r.found,
        [
            "Sellion",
            "Waist, Preferred, Post.",
            "Rt. Acromion",
            "Rt. Metacarpal Phal. II"
        ]
    );
    assert_eq!(r.missing.len(), 73 - 4);
    assert!(r.missing.contains(&"Lt. Axilla, Ant.".to_string()));
    assert_eq!(r.unknown, ["Nose Tip"]);
}

#[test]
fn lnd_detected_by_content_and_gzip() {
    use std::io::Write;
    let mut enc = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
    enc.write_all(lnd_file().as_bytes()).unwrap();
    let set = read_landmarks(&enc.finish().unwrap(), "landmarks.txt.gz").unwrap();
    assert_eq!(set.landmarks.len(), 5);
}

#[test]
fn lnd_broken_lines_name_the_line() {
    let text = "AUX =\n   1    0    1    0.000   abc   1.0   2.0 Sellion\nEND =\n";
    let err = read_landmarks(text.as_bytes(), "bad.lnd").unwrap_err();
    assert_eq!(
        err.to_string(),
        "bad.lnd: line 2: cannot read \"abc\" as a number in the line for \"Sellion\""
    );
    let err = read_landmarks(b"SUBJECT_ID = x\n1 2 3\n", "bad.lnd").unwrap_err();
    assert!(err.to_string().starts_with("bad.lnd: line 2: "), "{err}");
    let err = read_landmarks(b"SUBJECT_ID = x\n", "bad.lnd").unwrap_err();
    assert!(err.to_string().contains("AUX ="), "{err}");
}

#[test]
fn lnd_writer_round_trips_all_73_in_caesar_order() {
    let set = LandmarkSet {
        landmarks: vec![
            Landmark {
                name: "Crotch".into(),
                position: Point3::new(1.5, -2.25, 800.125),
            },
            Landmark {
                name: "Sellion".into(),
                position: Point3::new(0.0, 100.0, 1700.0),
            },
            Landmark {
                name: "Nose Tip".into(),
                position: Point3::new(5.0, 6.0, 7.0),
            },
        ],
        missing: vec![],
        unknown: vec!["Nose Tip".into()],
    };
    let bytes = write_lnd(&set, "synth_007");
    let text = String::from_utf8(bytes.clone()).unwrap();
    assert!(text.starts_with("SUBJECT_ID = synth_007\n"));
    let back = read_landmarks(&bytes, "landmarks_007.lnd").unwrap();
    assert_eq!(back.missing.len(), 71);
    assert_eq!(back.missing[0], CAESAR_LANDMARKS[1].name);
    assert_eq!(back.get("Crotch"), Some(Point3::new(1.5, -2.25, 800.125)));
    assert_eq!(back.get("Sellion"), Some(Point3::new(0.0, 100.0, 1700.0)));
    assert_eq!(back.unknown, ["Nose Tip"]);
    let names: Vec<&str> = back.landmarks.iter().map(|l| l.name.as_str()).collect();
    assert_eq!(names, ["Sellion", "Crotch", "Nose Tip"]);
}

#[test]
fn csv_with_header_quoted_names_crlf_and_missing_rows() {
    let text = "name,x,y,z\r\n\"Rt. Axilla, Ant.\",1,2,3\r\n\"Lt. Axilla, Post\", 4.5 , 5 ,6\r\nSellion,,,\r\nhead top,7,8,9\r\n";
    let set = read_landmarks(text.as_bytes(), "marks.csv").unwrap();
    assert_eq!(
        set.get("Rt. Axilla, Ant."),
        Some(Point3::new(1.0, 2.0, 3.0))
    );
    assert_eq!(
        set.get("Lt. Axilla, Post."),
        Some(Point3::new(4.5, 5.0, 6.0))
    );
    assert_eq!(set.missing, ["Sellion"]);
    assert_eq!(set.unknown, ["head top"]);
}

#[test]
fn csv_without_header_and_with_reordered_columns() {
    let set = read_landmarks(b"Crotch,1,2,3\nCervicale,4,5,6\n", "marks.csv").unwrap();
    assert_eq!(set.get("Cervicale"), Some(Point3::new(4.0, 5.0, 6.0)));
    let set = read_landmarks(b"X,Y,Z,Landmark\n1,2,3,crotch\n", "marks.csv").unwrap();
    assert_eq!(set.get("Crotch"), Some(Point3::new(1.0, 2.0, 3.0)));
}

#[test]
fn csv_writer_round_trips_names_with_commas() {
    let set = LandmarkSet {
        landmarks: vec![
            Landmark {
                name: "Waist, Preferred, Post.".into(),
                position: Point3::new(0.1, 0.2, 1.05),
            },
            Landmark {
                name: "Crotch".into(),
                position: Point3::new(-0.000123, 0.5, 0.8),
            },
        ],
        missing: vec![],
        unknown: vec![],
    };
    let bytes = write_landmarks_csv(&set);
    assert!(String::from_utf8_lossy(&bytes).starts_with("name,x,y,z\n\"Waist, Preferred, Post.\","));
    assert_eq!(read_landmarks(&bytes, "landmarks_001.csv").unwrap(), set);
}

#[test]
fn csv_broken_files() {
    let err = read_landmarks(b"name,x,y,z\nSellion,1,two,3\n", "m.csv").unwrap_err();
    assert_eq!(
        err.to_string(),
        "m.csv: line 2: cannot read \"two\" as a coordinate of \"Sellion\"; expected name,x,y,z"
    );
    let err = read_landmarks(b"Sellion,1,NaN,3\n", "m.csv").unwrap_err();
    assert_eq!(
        err.to_string(),
        "m.csv: landmark \"Sellion\" has a non-finite coordinate (NaN or infinity)"
    );
    let err = read_landmarks(
        b"Sellion,1,2,3\nsellion,4,5,6\nCrotch,1,1,1\nCROTCH,1,1,1\n",
        "m.csv",
    )
    .unwrap_err();
    assert_eq!(
        err,
        IoError::DuplicateLandmarks {
            file: "m.csv".into(),
            names: vec!["Sellion".into(), "Crotch".into()]
        }
    );
    assert_eq!(
        err.to_string(),
        "m.csv: landmarks Sellion, Crotch given more than once; keep one of each"
    );
    assert!(matches!(
        read_landmarks(b"", "m.csv"),
        Err(IoError::Empty { .. })
    ));
    assert!(read_landmarks(&[0xff, 0xfe, 0x00, 0x01], "m.csv").is_err());
}

#[test]
fn json_object_with_null_for_missing() {
    let text =
        r#"{"Sellion": [1, 2, 3], "rt acromion": [4.5, 5, 6e2], "Crotch": null, "belly": [0,0,0]}"#;
    let set = read_landmarks(text.as_bytes(), "marks.json").unwrap();
    assert_eq!(set.get("Rt. Acromion"), Some(Point3::new(4.5, 5.0, 600.0)));
    assert_eq!(set.missing, ["Crotch"]);
    assert_eq!(set.unknown, ["belly"]);
    // Detected by content, without the extension.
    assert_eq!(read_landmarks(text.as_bytes(), "upload").unwrap(), set);
}

#[test]
fn json_broken_files() {
    let err = read_landmarks(br#"{"Sellion": [1, 2]}"#, "m.json").unwrap_err();
    assert!(
        err.to_string().starts_with("m.json: line 1 column "),
        "{err}"
    );
    let err = read_landmarks(br#"{"Sellion": [1,2,3], "sellion": [1,2,3]}"#, "m.json").unwrap_err();
    assert!(matches!(err, IoError::DuplicateLandmarks { .. }), "{err}");
    let err = read_landmarks(b"[1, 2, 3]", "m.json").unwrap_err();
    assert!(err.to_string().starts_with("m.json: "), "{err}");
}
