//! Three finite coordinates from the words of a text line (OBJ `v`, ASCII STL `vertex`), with
//! errors that name the file, the line and the offending word or vertex.

use super::IoError;

/// Reads the next three words of a `keyword` line (number `line` of `file`) as finite numbers;
/// `what()` names the vertex or facet in the error for a non-finite one.
pub(crate) fn parse_xyz<'a>(
    words: &mut impl Iterator<Item = &'a str>,
    file: &str,
    line: usize,
    keyword: &str,
    what: impl FnOnce() -> String,
) -> Result<[f64; 3], IoError> {
    let mut p = [0.0f64; 3];
    for c in &mut p {
        let word = words.next().ok_or_else(|| {
            IoError::at_line(
                file,
                line,
                format!("a `{keyword}` line needs three coordinates"),
            )
        })?;
        *c = word.parse::<f64>().map_err(|_| {
            IoError::at_line(file, line, format!("cannot read {word:?} as a number"))
        })?;
    }
    if !p.iter().all(|c| c.is_finite()) {
        return Err(IoError::NonFinite {
            file: file.to_string(),
            what: what(),
        });
    }
    Ok(p)
}
