//! The PLY header: format, elements and their properties, and where the body starts.
//!
//! Grammar (Turk's PLY, as written by every scanner we know): `ply`, `format <ascii|binary_little_endian|
//! binary_big_endian> 1.0`, then `comment`/`obj_info` lines, `element <name> <count>` each followed by
//! `property <type> <name>` or `property list <count type> <item type> <name>`, then `end_header`.

use super::IoError;

/// Headers longer than this are not PLY headers (real ones are well under a kilobyte).
const MAX_HEADER_BYTES: usize = 1 << 20;

/// How the body of a PLY file is encoded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlyFormat {
    Ascii,
    BinaryLittleEndian,
    BinaryBigEndian,
}

/// A PLY scalar type, with both the classic names (`uchar`) and the sized aliases (`uint8`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ScalarType {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl ScalarType {
    fn parse(word: &str) -> Option<Self> {
        Some(match word {
            "char" | "int8" => ScalarType::I8,
            "uchar" | "uint8" => ScalarType::U8,
            "short" | "int16" => ScalarType::I16,
            "ushort" | "uint16" => ScalarType::U16,
            "int" | "int32" => ScalarType::I32,
            "uint" | "uint32" => ScalarType::U32,
            "float" | "float32" => ScalarType::F32,
            "double" | "float64" => ScalarType::F64,
            _ => return None,
        })
    }

    /// Size in bytes in a binary body.
    pub fn size(self) -> usize {
        match self {
            ScalarType::I8 | ScalarType::U8 => 1,
            ScalarType::I16 | ScalarType::U16 => 2,
            ScalarType::I32 | ScalarType::U32 | ScalarType::F32 => 4,
            ScalarType::F64 => 8,
        }
    }
}

/// What one property of an element holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PropertyKind {
    Scalar(ScalarType),
    List { count: ScalarType, item: ScalarType },
}

/// One `property` line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Property {
    pub name: String,
    pub kind: PropertyKind,
}

/// One `element` line with its properties.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Element {
    pub name: String,
    pub count: u64,
    pub properties: Vec<Property>,
}

impl Element {
    /// Whether every record has the same binary size (no list properties).
    pub fn is_fixed_size(&self) -> bool {
        self.properties
            .iter()
            .all(|p| matches!(p.kind, PropertyKind::Scalar(_)))
    }

    /// The element's name in plural for messages: "vertices", "faces", "edge elements".
    pub fn plural(&self) -> String {
        match self.name.as_str() {
            "vertex" => "vertices".to_string(),
            "face" => "faces".to_string(),
            other => format!("{other} elements"),
        }
    }
}

/// A parsed PLY header.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PlyHeader {
    pub format: PlyFormat,
    pub elements: Vec<Element>,
    /// Byte offset of the first body byte.
    pub body_offset: usize,
}

/// Whether `bytes` start with the PLY magic line.
pub fn is_ply(bytes: &[u8]) -> bool {
    bytes.starts_with(b"ply\n") || bytes.starts_with(b"ply\r\n") || bytes.starts_with(b"ply\r")
}

/// Parses the header of a PLY file.
pub fn parse_header(bytes: &[u8], file: &str) -> Result<PlyHeader, IoError> {
    if !is_ply(bytes) {
        return Err(IoError::malformed(
            file,
            "line 1",
            "a PLY file must start with the line `ply`",
        ));
    }
    let mut pos = 0usize;
    let mut line_no = 0usize;
    let mut format = None;
    let mut elements: Vec<Element> = Vec::new();
    loop {
        if pos >= bytes.len() || pos > MAX_HEADER_BYTES {
            return Err(IoError::malformed(
                file,
                "header",
                "no `end_header` line found; the file is not a complete PLY file",
            ));
        }
        let rest = &bytes[pos..];
        let end = rest.iter().position(|&b| b == b'\n').unwrap_or(rest.len());
        pos += (end + 1).min(rest.len());
        line_no += 1;
        let raw = &rest[..end];
        let raw = raw.strip_suffix(b"\r").unwrap_or(raw);
        let line = std::str::from_utf8(raw).map_err(|_| {
            IoError::at_line(file, line_no, "the PLY header contains non-text bytes")
        })?;
        let mut words = line.split_ascii_whitespace();
        let keyword = words.next().unwrap_or("");
        match keyword {
            "" | "comment" | "obj_info" => {}
            "ply" if line_no == 1 => {}
            "format" => {
                format = Some(match words.next() {
                    Some("ascii") => PlyFormat::Ascii,
                    Some("binary_little_endian") => PlyFormat::BinaryLittleEndian,
                    Some("binary_big_endian") => PlyFormat::BinaryBigEndian,
                    other => {
                        return Err(IoError::at_line(
                            file,
                            line_no,
                            format!("unknown PLY format {:?}; expected ascii, binary_little_endian or binary_big_endian", other.unwrap_or("")),
                        ))
                    }
                });
            }
            "element" => {
                let (Some(name), Some(count)) = (words.next(), words.next()) else {
                    return Err(IoError::at_line(
                        file,
                        line_no,
                        "an element line needs a name and a count",
                    ));
                };
                let count = count.parse::<u64>().map_err(|_| {
                    IoError::at_line(
                        file,
                        line_no,
                        format!("element {name} has count {count:?}, which is not a whole number"),
                    )
                })?;
                elements.push(Element {
                    name: name.to_string(),
                    count,
                    properties: Vec::new(),
                });
            }
            "property" => {
                let property = parse_property(&mut words).ok_or_else(|| {
                    IoError::at_line(
                        file,
                        line_no,
                        format!("cannot understand property line {line:?}"),
                    )
                })?;
                let Some(element) = elements.last_mut() else {
                    return Err(IoError::at_line(
                        file,
                        line_no,
                        "a property line comes before any element line",
                    ));
                };
                element.properties.push(property);
            }
            "end_header" => break,
            other => {
                return Err(IoError::at_line(
                    file,
                    line_no,
                    format!("unknown PLY header keyword {other:?}"),
                ))
            }
        }
    }
    let format = format
        .ok_or_else(|| IoError::malformed(file, "header", "the PLY header has no `format` line"))?;
    Ok(PlyHeader {
        format,
        elements,
        body_offset: pos,
    })
}

fn parse_property<'a>(words: &mut impl Iterator<Item = &'a str>) -> Option<Property> {
    let first = words.next()?;
    let kind = if first == "list" {
        let count = ScalarType::parse(words.next()?)?;
        let item = ScalarType::parse(words.next()?)?;
        if matches!(count, ScalarType::F32 | ScalarType::F64) {
            return None;
        }
        PropertyKind::List { count, item }
    } else {
        PropertyKind::Scalar(ScalarType::parse(first)?)
    };
    let name = words.next()?.to_string();
    Some(Property { name, kind })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_elements_properties_and_aliases() {
        let text = b"ply\r\nformat binary_big_endian 1.0\r\ncomment made by hand\r\nobj_info x\r\nelement vertex 3\r\nproperty float32 x\r\nproperty double y\r\nproperty int16 z\r\nelement face 1\r\nproperty list uint8 int32 vertex_index\r\nend_header\r\nBODY";
        let h = parse_header(text, "a.ply").unwrap();
        assert_eq!(h.format, PlyFormat::BinaryBigEndian);
        assert_eq!(h.elements.len(), 2);
        let kinds: Vec<_> = h.elements[0].properties.iter().map(|p| p.kind).collect();
        assert_eq!(
            kinds,
            [ScalarType::F32, ScalarType::F64, ScalarType::I16].map(PropertyKind::Scalar)
        );
        assert_eq!(
            h.elements[1].properties[0].kind,
            PropertyKind::List {
                count: ScalarType::U8,
                item: ScalarType::I32
            }
        );
        assert_eq!(&text[h.body_offset..], b"BODY");
    }

    #[test]
    fn rejects_bad_headers_with_line_numbers() {
        let err = parse_header(
            b"ply\nformat ascii 1.0\nelement vertex lots\nend_header\n",
            "s.ply",
        )
        .unwrap_err();
        assert_eq!(
            err.to_string(),
            "s.ply: line 3: element vertex has count \"lots\", which is not a whole number"
        );
        let err = parse_header(b"ply\nformat ascii 1.0\nproperty float x\n", "s.ply").unwrap_err();
        assert!(err.to_string().contains("line 3"), "{err}");
        let err = parse_header(b"ply\nformat ascii 1.0\nelement vertex 1\n", "s.ply").unwrap_err();
        assert!(err.to_string().contains("end_header"), "{err}");
    }
}
