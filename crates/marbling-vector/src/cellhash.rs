//! A fast hasher for integer grid-cell keys (multiply-rotate, as in rustc's FxHash):
//! the standard SipHash costs more than the geometry it indexes here.

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// Hasher state for small integer keys; not collision resistant against adversaries,
/// which grid cells of traced outlines are not.
#[derive(Clone, Copy, Debug, Default)]
pub struct CellHasher(u64);

const K: u64 = 0x517c_c1b7_2722_0a95;

impl Hasher for CellHasher {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }

    fn write_u64(&mut self, x: u64) {
        self.0 = (self.0.rotate_left(5) ^ x).wrapping_mul(K);
    }

    fn write_i64(&mut self, x: i64) {
        self.write_u64(x as u64);
    }
}

/// A hash map keyed by grid cells (column, row).
pub type CellMap<V> = HashMap<(i64, i64), V, BuildHasherDefault<CellHasher>>;
