//! Scan readers end to end on files built in the test: every PLY variant, OBJ face forms, both
//! STL kinds, gzip, writer round trips, and broken files.

use std::io::Write;

use bodyspace::io::{read_scan, write_obj, write_ply, write_ply_ascii, IoError};
use bodyspace::mesh::{summarise, Mesh, Units};
use nalgebra::Point3;

/// The unit square as two triangles (0 1 2) (0 2 3), and as one quad in files.
fn square_positions() -> [[f64; 3]; 4] {
    [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
    ]
}

fn assert_square(mesh: &Mesh) {
    let expected: Vec<Point3<f64>> = square_positions()
        .iter()
        .map(|p| Point3::new(p[0], p[1], p[2]))
        .collect();
    assert_eq!(mesh.positions, expected);
    assert_eq!(mesh.triangles, vec![[0, 1, 2], [0, 2, 3]]);
}

fn gzip(data: &[u8]) -> Vec<u8> {
    let mut enc = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    enc.write_all(data).unwrap();
    enc.finish().unwrap()
}

// ---------- PLY ----------

/// A PLY with vertex properties `nx ny nz x y z red green blue confidence` (all sorts of types)
/// and one quad face, plus an extra element with a list before and after, in `format`.
fn rich_ply(format: &str) -> Vec<u8> {
    let header = format!(
        "ply\nformat {format} 1.0\ncomment scanner output\nobj_info produced by a test\n\
         element camera 2\nproperty list uint16 float64 params\nproperty char id\n\
         element vertex 4\nproperty float nx\nproperty float ny\nproperty float nz\n\
         property double x\nproperty float32 y\nproperty int z\n\
         property uchar red\nproperty uint8 green\nproperty ushort blue\nproperty short s\nproperty uint u\n\
         property list uchar int texture\nproperty float confidence\n\
         element face 1\nproperty uchar flags\nproperty list ushort uint vertex_index\nproperty list int float texcoord\n\
         element edge 1\nproperty int vertex1\nproperty int vertex2\n\
         end_header\n"
    );
    let mut out = header.into_bytes();
    let big = format == "binary_big_endian";
    macro_rules! put {
        ($v:expr) => {
            if big {
                out.extend_from_slice(&$v.to_be_bytes())
            } else {
                out.extend_from_slice(&$v.to_le_bytes())
            }
        };
    }
    if format == "ascii" {
        out.extend_from_slice(b"3 0.5 1.5 2.5 -1\n0 7\n");
        for p in square_positions() {
            let line = format!(
                "0 0 1 {} {} {} 255 128 65535 -3 4000000000 2 9 9 0.75\n",
                p[0], p[1], p[2] as i32
            );
            out.extend_from_slice(line.as_bytes());
        }
        out.extend_from_slice(b"1 4 0 1 2 3 2 0.5 0.5\n0 1\n");
        return out;
    }
    for id in [-1i8, 7] {
        put!(2u16);
        put!(0.5f64);
        put!(1.5f64);
        put!(id);
    }
    for p in square_positions() {
        put!(0f32);
        put!(0f32);
        put!(1f32);
        put!(p[0]);
        put!(p[1] as f32);
        put!(p[2] as i32);
        put!(255u8);
        put!(128u8);
        put!(65535u16);
        put!(-3i16);
        put!(4_000_000_000u32);
        put!(2u8);
        put!(9i32);
        put!(9i32);
        put!(0.75f32);
    }
    put!(1u8);
    put!(4u16);
    for i in 0..4u32 {
        put!(i);
    }
    put!(2i32);
    put!(0.5f32);
    put!(0.5f32);
    put!(0i32);
    put!(1i32);
    out
}

#[test]
fn ply_ascii_binary_le_and_be_with_extra_properties_and_elements() {
    for format in ["ascii", "binary_little_endian", "binary_big_endian"] {
        let mesh =
            read_scan(&rich_ply(format), "scan.ply").unwrap_or_else(|e| panic!("{format}: {e}"));
        assert_square(&mesh);
    }
}

/// The square as one quad in the common scanner layout (fixed-size vertices with extras, faces
/// `list uchar int|uint`), which the binary fast path reads.
fn plain_binary_ply(big: bool, index_type: &str) -> Vec<u8> {
    let order = if big { "big" } else { "little" };
    let mut out = format!(
        "ply\nformat binary_{order}_endian 1.0\nelement vertex 4\nproperty float x\nproperty double y\n\
         property float z\nproperty uchar red\nelement face 1\nproperty list uchar {index_type} vertex_indices\nend_header\n"
    )
    .into_bytes();
    let swap = |b: &[u8]| -> Vec<u8> {
        if big {
            b.iter().rev().copied().collect()
        } else {
            b.to_vec()
        }
    };
    for p in square_positions() {
        out.extend(swap(&(p[0] as f32).to_le_bytes()));
        out.extend(swap(&p[1].to_le_bytes()));
        out.extend(swap(&(p[2] as f32).to_le_bytes()));
        out.push(200);
    }
    out.push(4);
    for i in 0..4u32 {
        out.extend(swap(&i.to_le_bytes()));
    }
    out
}

#[test]
fn ply_common_binary_layouts_in_both_byte_orders() {
    for big in [false, true] {
        for index_type in ["int", "uint", "int32", "uint32"] {
            let mesh = read_scan(&plain_binary_ply(big, index_type), "scan.ply").unwrap();
            assert_square(&mesh);
        }
    }
    let mut bytes = plain_binary_ply(true, "int");
    let n = bytes.len();
    bytes[n - 1] = 9; // the last index (big-endian low byte) → 9
    let err = read_scan(&bytes, "scan.ply").unwrap_err();
    assert_eq!(
        err.to_string(),
        "scan.ply: face 0 refers to vertex 9 but the file has 4 vertices"
    );
}

#[test]
fn ply_crlf_header_and_polygons_are_fan_triangulated() {
    let text = "ply\r\nformat ascii 1.0\r\nelement vertex 5\r\nproperty float x\r\nproperty float y\r\nproperty float z\r\n\
                element face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\n\
                0 0 0\r\n1 0 0\r\n1 1 0\r\n0.5 1.5 0\r\n0 1 0\r\n5 0 1 2 3 4\r\n";
    let mesh = read_scan(text.as_bytes(), "pentagon.ply").unwrap();
    assert_eq!(mesh.triangles, vec![[0, 1, 2], [0, 2, 3], [0, 3, 4]]);
}

#[test]
fn ply_point_cloud_without_faces_is_read() {
    let text = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n4 5 6\n";
    let mesh = read_scan(text.as_bytes(), "cloud.ply").unwrap();
    assert_eq!(mesh.positions.len(), 2);
    assert!(mesh.triangles.is_empty());
}

fn binary_header(vertices: u64, faces: u64) -> Vec<u8> {
    format!(
        "ply\nformat binary_little_endian 1.0\nelement vertex {vertices}\nproperty float x\nproperty float y\nproperty float z\n\
         element face {faces}\nproperty list uchar int vertex_indices\nend_header\n"
    )
    .into_bytes()
}

#[test]
fn ply_truncated_vertices_say_how_many_were_there() {
    let mut bytes = binary_header(120_000, 1);
    bytes.extend(std::iter::repeat_n(0u8, 31_002 * 12 + 5));
    let err = read_scan(&bytes, "scan.ply").unwrap_err();
    assert_eq!(
        err.to_string(),
        "scan.ply: header declares 120000 vertices but the file ends after 31002"
    );
}

#[test]
fn ply_truncated_faces_say_how_many_were_there() {
    let mesh = Mesh::new(
        vec![
            Point3::origin(),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
        ],
        vec![[0, 1, 2]; 10],
    );
    let mut bytes = write_ply(&mesh);
    bytes.truncate(bytes.len() - 13 * 3 - 4);
    let err = read_scan(&bytes, "scan.ply").unwrap_err();
    assert_eq!(
        err,
        IoError::Truncated {
            file: "scan.ply".into(),
            what: "faces".into(),
            declared: 10,
            found: 6
        }
    );
}

#[test]
fn ply_header_claiming_two_billion_vertices_fails_fast() {
    for (v, f) in [(1u64 << 31, 0u64), (3, 1u64 << 40), (u64::MAX, 1)] {
        let mut bytes = binary_header(v, f);
        bytes.extend_from_slice(&[0u8; 36]);
        let err = read_scan(&bytes, "huge.ply").unwrap_err();
        assert!(matches!(err, IoError::Truncated { .. }), "{err}");
    }
    let ascii = "ply\nformat ascii 1.0\nelement vertex 2147483648\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n";
    let err = read_scan(ascii.as_bytes(), "huge.ply").unwrap_err();
    assert!(err.to_string().contains("ends after 1"), "{err}");
}

#[test]
fn ply_nan_coordinate_names_the_vertex() {
    let text = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n1 1 1\n2 nan 2\n";
    let err = read_scan(text.as_bytes(), "scan.ply").unwrap_err();
    assert_eq!(
        err.to_string(),
        "scan.ply: vertex 2 has a non-finite coordinate (NaN or infinity)"
    );
    let mut bytes = binary_header(1, 0);
    for c in [0.0f32, f32::INFINITY, 0.0] {
        bytes.extend_from_slice(&c.to_le_bytes());
    }
    assert!(matches!(
        read_scan(&bytes, "scan.ply"),
        Err(IoError::NonFinite { .. })
    ));
}

#[test]
fn ply_out_of_range_and_negative_indices_are_errors() {
    for bad in ["3 0 1 3", "3 0 -1 2"] {
        let text = format!("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n{bad}\n");
        let err = read_scan(text.as_bytes(), "scan.ply").unwrap_err();
        assert!(
            matches!(
                err,
                IoError::IndexOutOfRange {
                    face: 0,
                    vertex_count: 3,
                    ..
                }
            ),
            "{err}"
        );
    }
}

#[test]
fn ply_binary_triangle_fast_path_checks_indices() {
    let positions = vec![
        Point3::origin(),
        Point3::new(1.0, 0.0, 0.0),
        Point3::new(0.0, 1.0, 0.0),
    ];
    let bad = Mesh::new(positions, vec![[0, 1, 2], [0, 1, 5]]);
    let err = read_scan(&write_ply(&bad), "scan.ply").unwrap_err();
    assert_eq!(
        err.to_string(),
        "scan.ply: face 1 refers to vertex 5 but the file has 3 vertices"
    );
}

#[test]
fn ply_bad_tokens_and_missing_coordinates_are_errors() {
    let text = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 zero 0\n";
    let err = read_scan(text.as_bytes(), "scan.ply").unwrap_err();
    assert_eq!(
        err.to_string(),
        "scan.ply: vertex 0: cannot read \"zero\" as a number"
    );
    let text = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n";
    let err = read_scan(text.as_bytes(), "scan.ply").unwrap_err();
    assert!(err.to_string().contains("`z`"), "{err}");
}

#[test]
fn ply_round_trips_through_both_writers() {
    let mesh = Mesh::new(
        vec![
            Point3::new(0.25, -1.5, 3.0),
            Point3::new(1.0, 2.0, 0.125),
            Point3::new(-4.0, 0.5, 1.0),
            Point3::new(7.0, 8.0, 9.0),
        ],
        vec![[0, 1, 2], [2, 1, 3]],
    );
    for bytes in [write_ply(&mesh), write_ply_ascii(&mesh), write_obj(&mesh)] {
        let back = read_scan(&bytes, "round.ply").unwrap();
        assert_eq!(back, mesh);
    }
    let obj = read_scan(&write_obj(&mesh), "round.obj").unwrap();
    assert_eq!(obj, mesh);
}

// ---------- OBJ ----------

#[test]
fn obj_all_face_forms_polygons_and_negative_indices() {
    let text = "# a comment\nmtllib body.mtl\no body\ng skin\ns 1\nusemtl skin\n\
                v 0 0 0\nv 1 0 0\nv 1 1 0 0.5 0.5 0.5\nv 0 1 0\n\
                vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n\
                f 1 2 3\nf 1/1 3/3 4/1\nf 1//1 2//1 3//1\nf 1/1/1 3/3/1 4/2/1\n\
                f -4 -3 -2 -1\nf -4/1/1 -2/2/1 \\\n -1/3/1\n";
    let mesh = read_scan(text.as_bytes(), "forms.obj").unwrap();
    assert_eq!(mesh.positions.len(), 4);
    assert_eq!(
        mesh.triangles,
        vec![
            [0, 1, 2],
            [0, 2, 3],
            [0, 1, 2],
            [0, 2, 3],
            [0, 1, 2],
            [0, 2, 3],
            [0, 2, 3]
        ]
    );
}

#[test]
fn obj_detected_by_content_without_extension() {
    let text = "v 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\nf 1 2 3 4\r\n";
    assert_square(&read_scan(text.as_bytes(), "upload").unwrap());
}

#[test]
fn obj_broken_files_name_the_line() {
    let cases = [
        (
            "v 0 0 0\nv 1 0\n",
            "forms.obj: line 2: a `v` line needs three coordinates",
        ),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n",
            "forms.obj: face 1 refers to vertex 4 but the file has 3 vertices",
        ),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n",
            "forms.obj: line 4: face index 0; OBJ indices start at 1 (or are negative)",
        ),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n",
            "forms.obj: face 1 refers to vertex -4 but the file has 3 vertices",
        ),
        (
            "v 0 0 0\nv 1 0 0\nf 1 2\n",
            "forms.obj: line 3: face has 2 corners; a face needs at least 3",
        ),
        (
            "v 0 inf 0\n",
            "forms.obj: vertex 1 (line 1) has a non-finite coordinate (NaN or infinity)",
        ),
        (
            "# nothing\n",
            "forms.obj: no `v` vertex lines found; is this an OBJ file?",
        ),
    ];
    for (text, message) in cases {
        let err = read_scan(text.as_bytes(), "forms.obj").unwrap_err();
        assert_eq!(err.to_string(), message);
    }
}

// ---------- STL ----------

fn binary_stl(header: &[u8], triangles: &[[[f32; 3]; 3]]) -> Vec<u8> {
    let mut out = vec![b' '; 80];
    out[..header.len()].copy_from_slice(header);
    out.extend_from_slice(&(triangles.len() as u32).to_le_bytes());
    for t in triangles {
        out.extend_from_slice(&[0u8; 12]);
        for c in t.iter().flatten() {
            out.extend_from_slice(&c.to_le_bytes());
        }
        out.extend_from_slice(&[0u8; 2]);
    }
    out
}

const SQUARE_STL: [[[f32; 3]; 3]; 2] = [
    [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]],
    [[0.0, 0.0, -0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]],
];

#[test]
fn stl_binary_even_when_it_starts_with_solid_and_merges_corners() {
    for header in [&b"binary stl"[..], &b"solid but binary"[..]] {
        let mesh = read_scan(&binary_stl(header, &SQUARE_STL), "scan.stl").unwrap();
        assert_square(&mesh);
        let s = summarise(&mesh);
        assert_eq!((s.boundary_loops, s.components), (1, 1));
    }
}

#[test]
fn stl_ascii_is_read_and_merged() {
    let mut text = String::from("solid square\r\n");
    for t in SQUARE_STL {
        text.push_str("  facet normal 0 0 1\r\n    outer loop\r\n");
        for c in t {
            text.push_str(&format!("      vertex {} {} {}\r\n", c[0], c[1], c[2]));
        }
        text.push_str("    endloop\r\n  endfacet\r\n");
    }
    text.push_str("endsolid square\r\n");
    assert_square(&read_scan(text.as_bytes(), "scan.stl").unwrap());
}

#[test]
fn stl_truncated_binary_is_an_error() {
    let mut bytes = binary_stl(b"x", &SQUARE_STL);
    bytes.truncate(84 + 50 + 20);
    let err = read_scan(&bytes, "scan.stl").unwrap_err();
    assert_eq!(
        err.to_string(),
        "scan.stl: header declares 2 triangles but the file ends after 1"
    );
}

// ---------- gzip, detection, garbage ----------

#[test]
fn gzip_is_detected_by_magic_bytes_for_every_format() {
    let mesh = Mesh::new(
        vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(900.0, 0.0, 0.0),
            Point3::new(0.0, 1800.0, 0.0),
        ],
        vec![[0, 1, 2]],
    );
    for (bytes, name) in [
        (write_ply(&mesh), "scan.ply.gz"),
        (write_obj(&mesh), "scan.obj.gz"),
        (write_ply(&mesh), "scan.bin"),
    ] {
        let back = read_scan(&gzip(&bytes), name).unwrap();
        assert_eq!(back.triangles, mesh.triangles);
        assert_eq!(summarise(&back).units_detected, Units::Millimetres);
    }
}

#[test]
fn empty_garbage_and_unknown_files_are_one_line_errors() {
    let err = read_scan(b"", "empty.ply").unwrap_err();
    assert_eq!(err.to_string(), "empty.ply: the file is empty");
    let garbage: Vec<u8> = (0..1000u32)
        .map(|i| (i.wrapping_mul(2654435761) >> 13) as u8)
        .collect();
    let err = read_scan(&garbage, "noise.dat").unwrap_err();
    assert!(matches!(err, IoError::UnknownFormat { .. }), "{err}");
    for name in ["noise.ply", "noise.obj", "noise.stl", "noise.ply.gz"] {
        let err = read_scan(&garbage, name).unwrap_err();
        let message = err.to_string();
        assert!(message.starts_with(&format!("{name}: ")), "{message}");
        assert!(!message.contains('\n'), "{message}");
    }
    let err = read_scan(&gzip(b""), "empty.ply.gz").unwrap_err();
    assert_eq!(err.to_string(), "empty.ply.gz: the file is empty");
    let mut bad = gzip(b"ply\nformat ascii 1.0\n");
    bad.truncate(12);
    assert!(matches!(
        read_scan(&bad, "cut.ply.gz"),
        Err(IoError::Gzip { .. })
    ));
}

#[test]
fn every_prefix_of_a_valid_file_fails_cleanly_or_parses() {
    for bytes in [
        rich_ply("binary_little_endian"),
        rich_ply("ascii"),
        binary_stl(b"x", &SQUARE_STL),
    ] {
        for cut in 0..bytes.len() {
            // Must never panic; a prefix may still be a valid (smaller) file.
            let _ = read_scan(&bytes[..cut], "cut.ply");
        }
    }
}

#[test]
fn corrupted_bytes_never_panic() {
    // Deterministic byte flips over every kind of file: each read must return Ok or Err.
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    let files = [
        (rich_ply("binary_little_endian"), "a.ply"),
        (rich_ply("binary_big_endian"), "a.ply"),
        (rich_ply("ascii"), "a.ply"),
        (plain_binary_ply(false, "int"), "a.ply"),
        (binary_stl(b"x", &SQUARE_STL), "a.stl"),
        (
            b"v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nf -1 -2 -3\n".to_vec(),
            "a.obj",
        ),
    ];
    for (bytes, name) in files {
        for _ in 0..300 {
            let mut b = bytes.clone();
            for _ in 0..1 + next() % 4 {
                let i = (next() % b.len() as u64) as usize;
                b[i] = next() as u8;
            }
            let _ = read_scan(&b, name);
        }
    }
}
