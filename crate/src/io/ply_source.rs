//! Where PLY record values come from: the binary body (either byte order) or the ASCII token
//! stream. The record readers in `ply_read` are generic over [`Source`], so one reader serves all
//! three encodings.

use super::ply_header::ScalarType;

/// Why a record could not be read.
pub(super) enum Fail {
    /// The data ended.
    End,
    /// A value could not be understood (ASCII only); the text says which.
    Bad(String),
}

/// Where record values come from: the binary body or the ASCII token stream.
pub(super) trait Source {
    fn scalar(&mut self, t: ScalarType) -> Result<f64, Fail>;
    fn skip(&mut self, t: ScalarType) -> Result<(), Fail>;
    fn remaining(&self) -> usize;
    /// Whether values have fixed binary sizes (so `remaining / record size` counts whole records).
    const BINARY: bool;
    /// Smallest number of bytes one value of type `t` can take.
    fn min_value_bytes(t: ScalarType) -> usize;
    /// The raw body, read position and byte order, for the binary fast paths.
    fn binary_parts(&mut self) -> Option<(&[u8], &mut usize, bool)> {
        None
    }
}

pub(super) struct Binary<'a> {
    pub(super) bytes: &'a [u8],
    pub(super) pos: usize,
    pub(super) big_endian: bool,
}

impl Binary<'_> {
    #[inline(always)]
    fn take<const N: usize>(&mut self) -> Result<[u8; N], Fail> {
        let end = self.pos + N;
        let chunk = self.bytes.get(self.pos..end).ok_or(Fail::End)?;
        self.pos = end;
        let mut out = [0u8; N];
        out.copy_from_slice(chunk);
        Ok(out)
    }
}

macro_rules! endian {
    ($self:ident, $ty:ty, $n:literal) => {{
        let b = $self.take::<$n>()?;
        if $self.big_endian {
            <$ty>::from_be_bytes(b)
        } else {
            <$ty>::from_le_bytes(b)
        }
    }};
}

impl Source for Binary<'_> {
    const BINARY: bool = true;

    #[inline(always)]
    fn scalar(&mut self, t: ScalarType) -> Result<f64, Fail> {
        Ok(match t {
            ScalarType::I8 => endian!(self, i8, 1) as f64,
            ScalarType::U8 => endian!(self, u8, 1) as f64,
            ScalarType::I16 => endian!(self, i16, 2) as f64,
            ScalarType::U16 => endian!(self, u16, 2) as f64,
            ScalarType::I32 => endian!(self, i32, 4) as f64,
            ScalarType::U32 => endian!(self, u32, 4) as f64,
            ScalarType::F32 => endian!(self, f32, 4) as f64,
            ScalarType::F64 => endian!(self, f64, 8),
        })
    }

    #[inline(always)]
    fn skip(&mut self, t: ScalarType) -> Result<(), Fail> {
        let end = self.pos + t.size();
        if end > self.bytes.len() {
            return Err(Fail::End);
        }
        self.pos = end;
        Ok(())
    }

    fn remaining(&self) -> usize {
        self.bytes.len().saturating_sub(self.pos)
    }

    fn min_value_bytes(t: ScalarType) -> usize {
        t.size()
    }

    fn binary_parts(&mut self) -> Option<(&[u8], &mut usize, bool)> {
        Some((self.bytes, &mut self.pos, self.big_endian))
    }
}

pub(super) struct Ascii<'a> {
    pub(super) bytes: &'a [u8],
    pub(super) pos: usize,
}

impl<'a> Ascii<'a> {
    fn token(&mut self) -> Result<&'a [u8], Fail> {
        let bytes = self.bytes;
        while self.pos < bytes.len() && bytes[self.pos].is_ascii_whitespace() {
            self.pos += 1;
        }
        let start = self.pos;
        while self.pos < bytes.len() && !bytes[self.pos].is_ascii_whitespace() {
            self.pos += 1;
        }
        if start == self.pos {
            Err(Fail::End)
        } else {
            Ok(&bytes[start..self.pos])
        }
    }
}

impl Source for Ascii<'_> {
    const BINARY: bool = false;

    fn scalar(&mut self, _t: ScalarType) -> Result<f64, Fail> {
        let token = self.token()?;
        std::str::from_utf8(token)
            .ok()
            .and_then(|s| s.parse::<f64>().ok())
            .ok_or_else(|| {
                Fail::Bad(format!(
                    "cannot read {:?} as a number",
                    String::from_utf8_lossy(token)
                ))
            })
    }

    fn skip(&mut self, _t: ScalarType) -> Result<(), Fail> {
        self.token().map(|_| ())
    }

    fn remaining(&self) -> usize {
        self.bytes.len().saturating_sub(self.pos)
    }

    fn min_value_bytes(_t: ScalarType) -> usize {
        // One digit and one separator.
        2
    }
}
