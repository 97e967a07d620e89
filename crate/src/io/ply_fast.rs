//! Fast paths of the binary PLY reader for the layouts nearly every scanner writes: vertex
//! records of fixed size (x y z plus any scalar extras) and faces that are a single
//! `list uchar int|uint` property. They read straight from the byte slice with one bounds check
//! per record; anything else falls back to the general record reader in `ply_read`.

use nalgebra::Point3;

use super::limits::{too_many_triangles, MAX_SCAN_TRIANGLES};
use super::ply_header::{Element, PropertyKind, ScalarType};
use super::IoError;

#[inline(always)]
fn bytes_at<const N: usize>(record: &[u8], offset: usize) -> [u8; N] {
    let mut out = [0u8; N];
    out.copy_from_slice(&record[offset..offset + N]);
    out
}

#[inline(always)]
fn value(record: &[u8], (offset, t): (usize, ScalarType), big: bool) -> f64 {
    macro_rules! get {
        ($ty:ty, $n:literal) => {{
            let b = bytes_at::<$n>(record, offset);
            if big {
                <$ty>::from_be_bytes(b)
            } else {
                <$ty>::from_le_bytes(b)
            }
        }};
    }
    match t {
        ScalarType::F32 => get!(f32, 4) as f64,
        ScalarType::F64 => get!(f64, 8),
        ScalarType::I8 => get!(i8, 1) as f64,
        ScalarType::U8 => get!(u8, 1) as f64,
        ScalarType::I16 => get!(i16, 2) as f64,
        ScalarType::U16 => get!(u16, 2) as f64,
        ScalarType::I32 => get!(i32, 4) as f64,
        ScalarType::U32 => get!(u32, 4) as f64,
    }
}

/// Reads a fixed-size vertex element at `*pos`; `None` when the layout does not qualify.
/// The caller has checked that `count · stride` bytes remain.
pub(super) fn fixed_vertices(
    bytes: &[u8],
    pos: &mut usize,
    big: bool,
    element: &Element,
    positions: &mut Vec<Point3<f64>>,
    file: &str,
) -> Option<Result<(), IoError>> {
    let mut stride = 0usize;
    let mut axes = [None; 3];
    for p in &element.properties {
        let PropertyKind::Scalar(t) = p.kind else {
            return None;
        };
        let axis = match p.name.as_str() {
            "x" => Some(0),
            "y" => Some(1),
            "z" => Some(2),
            _ => None,
        };
        if let Some(a) = axis {
            axes[a] = Some((stride, t));
        }
        stride += t.size();
    }
    let [Some(x), Some(y), Some(z)] = axes else {
        return None;
    };
    let end = pos.checked_add(usize::try_from(element.count).ok()?.checked_mul(stride)?)?;
    let body = bytes.get(*pos..end)?;
    for (i, record) in body.chunks_exact(stride).enumerate() {
        let p = [
            value(record, x, big),
            value(record, y, big),
            value(record, z, big),
        ];
        if !p.iter().all(|c| c.is_finite()) {
            return Some(Err(IoError::NonFinite {
                file: file.to_string(),
                what: format!("vertex {i}"),
            }));
        }
        positions.push(Point3::new(p[0], p[1], p[2]));
    }
    *pos = end;
    Some(Ok(()))
}

/// Reads a face element whose only property is `list uchar int|uint vertex_indices` at `*pos`,
/// fan-triangulating polygons; `None` when the layout does not qualify.
pub(super) fn uchar_int_faces(
    bytes: &[u8],
    pos: &mut usize,
    big: bool,
    element: &Element,
    vertex_count: u64,
    triangles: &mut Vec<[u32; 3]>,
    file: &str,
) -> Option<Result<(), IoError>> {
    let [property] = element.properties.as_slice() else {
        return None;
    };
    let signed = match property.kind {
        PropertyKind::List {
            count: ScalarType::U8,
            item: ScalarType::I32,
        } => true,
        PropertyKind::List {
            count: ScalarType::U8,
            item: ScalarType::U32,
        } => false,
        _ => return None,
    };
    if property.name != "vertex_indices" && property.name != "vertex_index" {
        return None;
    }
    let index = |b: [u8; 4]| -> i64 {
        match (signed, big) {
            (true, false) => i32::from_le_bytes(b) as i64,
            (true, true) => i32::from_be_bytes(b) as i64,
            (false, false) => u32::from_le_bytes(b) as i64,
            (false, true) => u32::from_be_bytes(b) as i64,
        }
    };
    let mut p = *pos;
    let mut polygon: Vec<u32> = Vec::with_capacity(8);
    for face in 0..element.count {
        let truncated = || IoError::Truncated {
            file: file.to_string(),
            what: element.plural(),
            declared: element.count,
            found: face,
        };
        let Some(&n) = bytes.get(p) else {
            return Some(Err(truncated()));
        };
        let n = n as usize;
        let Some(items) = bytes.get(p + 1..p + 1 + 4 * n) else {
            return Some(Err(truncated()));
        };
        p += 1 + 4 * n;
        let out_of_range = |v: i64| {
            Some(Err(IoError::IndexOutOfRange {
                file: file.to_string(),
                face,
                index: v,
                vertex_count,
            }))
        };
        if n == 3 {
            // Triangles are nearly every face of a scan: no polygon buffer.
            let t = [0, 4, 8].map(|o| index(bytes_at::<4>(items, o)));
            if let Some(&v) = t.iter().find(|&&v| v < 0 || v as u64 >= vertex_count) {
                return out_of_range(v);
            }
            if triangles.len() as u64 >= MAX_SCAN_TRIANGLES {
                return Some(Err(too_many_triangles(file)));
            }
            triangles.push(t.map(|v| v as u32));
            continue;
        }
        polygon.clear();
        for k in 0..n {
            let v = index(bytes_at::<4>(items, 4 * k));
            if v < 0 || v as u64 >= vertex_count {
                return out_of_range(v);
            }
            polygon.push(v as u32);
        }
        if (triangles.len() + n) as u64 > MAX_SCAN_TRIANGLES + 2 {
            return Some(Err(too_many_triangles(file)));
        }
        for k in 1..n.saturating_sub(1) {
            triangles.push([polygon[0], polygon[k], polygon[k + 1]]);
        }
    }
    *pos = p;
    Some(Ok(()))
}
