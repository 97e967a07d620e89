//! Per-vertex region flags of the template (a bit set).

/// Region flags of one template vertex. The paper gives hands and ears data weight 0.1; soles
/// are never seen by a standing scanner; `UNSEEN` marks surface no scanner can see (the inner
/// mouth cavity, deep nostrils) which an aligner must not drag around.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct RegionFlags(pub u8);

impl RegionFlags {
    pub const HAND: u8 = 1;
    pub const EAR: u8 = 2;
    pub const SOLE: u8 = 4;
    pub const UNSEEN: u8 = 8;
    /// Flag names and bits, as written in the template file header.
    pub const NAMES: [(&'static str, u8); 4] = [
        ("hand", Self::HAND),
        ("ear", Self::EAR),
        ("sole", Self::SOLE),
        ("unseen", Self::UNSEEN),
    ];

    pub fn hand(self) -> bool {
        self.0 & Self::HAND != 0
    }
    pub fn ear(self) -> bool {
        self.0 & Self::EAR != 0
    }
    pub fn sole(self) -> bool {
        self.0 & Self::SOLE != 0
    }
    pub fn unseen(self) -> bool {
        self.0 & Self::UNSEEN != 0
    }
    /// Whether any of `bits` is set.
    pub fn any(self, bits: u8) -> bool {
        self.0 & bits != 0
    }
}
