//! Which side of the playground is open: marbling or the noise playground.

/// Which side of the playground is open.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Marbling: the design and its tools.
    Marbling,
    /// The noise playground.
    Noise,
}

impl Mode {
    /// The name shown in `data-mode`: `marbling` or `noise`.
    pub fn name(self) -> &'static str {
        match self {
            Mode::Marbling => "marbling",
            Mode::Noise => "noise",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_what_automation_reads() {
        assert_eq!(Mode::Marbling.name(), "marbling");
        assert_eq!(Mode::Noise.name(), "noise");
    }
}
