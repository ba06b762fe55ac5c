//! Pipelines compiled per [`ExactVariant`] on first use: a design's noise types pick its
//! module, so the set grows with the designs met (a handful in practice).

use crate::shaders::ExactVariant;
use std::sync::Mutex;

/// The pipelines of type `P` built so far, one per variant.
#[derive(Debug)]
pub struct Variants<P> {
    built: Mutex<Vec<(ExactVariant, P)>>,
}

impl<P> Default for Variants<P> {
    fn default() -> Self {
        Self {
            built: Mutex::new(Vec::new()),
        }
    }
}

impl<P: Clone> Variants<P> {
    /// The pipeline of `variant`, if built.
    pub fn get(&self, variant: ExactVariant) -> Option<P> {
        let built = self.built.lock().unwrap_or_else(|e| e.into_inner());
        built
            .iter()
            .find(|(v, _)| *v == variant)
            .map(|(_, p)| p.clone())
    }

    /// The pipeline of `variant`, built by `build` the first time.
    pub fn get_or_init(&self, variant: ExactVariant, build: impl FnOnce() -> P) -> P {
        if let Some(p) = self.get(variant) {
            return p;
        }
        let p = build();
        let mut built = self.built.lock().unwrap_or_else(|e| e.into_inner());
        built.push((variant, p.clone()));
        p
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_variant_is_built_once() {
        let v: Variants<u32> = Variants::default();
        let mut builds = 0;
        for variant in ExactVariant::ALL.into_iter().chain(ExactVariant::ALL) {
            v.get_or_init(variant, || {
                builds += 1;
                builds
            });
        }
        assert_eq!(builds as usize, ExactVariant::ALL.len());
        assert_eq!(v.get(ExactVariant::ALL[2]), Some(3));
    }
}
