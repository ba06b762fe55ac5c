//! `--size`: an output size written `N` (square) or `WxH`.

use std::fmt;
use std::str::FromStr;

/// Output size in pixels, both sides ≥ 1.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Size {
    /// Width, pixels.
    pub width: u32,
    /// Height, pixels.
    pub height: u32,
}

impl FromStr for Size {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let side = |t: &str| match t.trim().parse::<u32>() {
            Ok(v) if v > 0 => Ok(v),
            _ => Err(format!("expected a size like 1024 or 1920x1080, got {s:?}")),
        };
        let (width, height) = match s.split_once(['x', 'X', '×']) {
            Some((w, h)) => (side(w)?, side(h)?),
            None => (side(s)?, side(s)?),
        };
        Ok(Self { width, height })
    }
}

impl fmt::Display for Size {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}×{}", self.width, self.height)
    }
}

#[cfg(test)]
mod tests {
    use super::Size;

    #[test]
    fn parses_square_and_rectangles() {
        assert_eq!(
            "1024".parse(),
            Ok(Size {
                width: 1024,
                height: 1024
            })
        );
        assert_eq!(
            "1920x1080".parse(),
            Ok(Size {
                width: 1920,
                height: 1080
            })
        );
        assert!("0x5".parse::<Size>().is_err());
        assert!("12x".parse::<Size>().is_err());
    }
}
