//! The host mirror of `NoiseStack` (shaders/layers.wgsl): a spec with its layers as one
//! uniform, for evaluating the stack's intensity on the GPU (`stack_intensity`). Keep in
//! sync with the WGSL.

use crate::layer::MAX_LAYERS;
use crate::noise_gpu::{GpuUnsupported, NoiseGpu};
use crate::spec::{NoiseSpec, Transfer};
use bytemuck::{Pod, Zeroable};

/// Noise slots: the base, then a layer and its mask per layer.
pub const STACK_SLOTS: usize = 1 + 2 * MAX_LAYERS;

/// Host mirror of WGSL `StackTransfer`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct StackTransferGpu {
    /// Threshold centre, noise units.
    pub threshold: f32,
    /// Threshold width, noise units.
    pub width: f32,
    /// 0 default grey map, 1 threshold, 2 inverted threshold.
    pub transfer: u32,
    /// Padding.
    pub _pad: u32,
}

/// Host mirror of WGSL `StackLayer`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct StackLayerGpu {
    /// `Combine::index`.
    pub combine: u32,
    /// Fade in [0, 1].
    pub weight: f32,
    /// Padding.
    pub _pad: [u32; 2],
}

/// Host mirror of WGSL `NoiseStack`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Pod, Zeroable)]
pub struct NoiseStackGpu {
    /// Layers in use.
    pub layer_count: u32,
    /// Padding.
    pub _pad: [u32; 3],
    /// Slot 0 the base noise, 1 + 2i layer i, 2 + 2i its mask.
    pub noises: [NoiseGpu; STACK_SLOTS],
    /// Each slot's transfer.
    pub transfers: [StackTransferGpu; STACK_SLOTS],
    /// Each layer's combine mode and weight.
    pub layers: [StackLayerGpu; MAX_LAYERS],
}

/// Why a stack has no GPU form.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum StackUnsupported {
    /// A noise of the stack has no WGSL form.
    #[error(transparent)]
    Noise(#[from] GpuUnsupported),
    /// The WGSL stack applies the default grey map or a threshold only.
    #[error("{0}: the WGSL stack takes only the default or a threshold transfer")]
    Transfer(String),
}

fn transfer(spec: &NoiseSpec, slot: &str) -> Result<StackTransferGpu, StackUnsupported> {
    match &spec.transfer {
        None => Ok(StackTransferGpu::default()),
        Some(Transfer::Threshold(t)) => Ok(StackTransferGpu {
            threshold: t.threshold,
            width: t.width,
            transfer: if t.invert { 2 } else { 1 },
            _pad: 0,
        }),
        Some(_) => Err(StackUnsupported::Transfer(slot.to_owned())),
    }
}

impl NoiseStackGpu {
    /// The stack of `spec` (its noise and layers; palette and blend apply after) at
    /// output size `size`.
    pub fn from_spec(spec: &NoiseSpec, size: u32) -> Result<Self, StackUnsupported> {
        // An absent mask costs a white-noise lookup.
        let cheap = NoiseGpu {
            noise_type: crate::wgsl::NoiseKind::White as u32,
            ..NoiseGpu::default()
        };
        let mut s = Self {
            layer_count: spec.layers.len().min(MAX_LAYERS) as u32,
            _pad: [0; 3],
            noises: [cheap; STACK_SLOTS],
            transfers: [StackTransferGpu::default(); STACK_SLOTS],
            layers: [StackLayerGpu::default(); MAX_LAYERS],
        };
        s.noises[0] = NoiseGpu::from_spec(spec, size)?;
        s.transfers[0] = transfer(spec, "transfer")?;
        for (i, l) in spec.layers.iter().take(MAX_LAYERS).enumerate() {
            let noise = NoiseSpec {
                tile: l.noise.tile.or(spec.tile),
                ..l.noise.clone()
            };
            s.noises[1 + 2 * i] = NoiseGpu::from_spec(&noise, size)?;
            s.transfers[1 + 2 * i] = transfer(&noise, &format!("layers[{i}].transfer"))?;
            if let Some(m) = &l.mask {
                let mask = NoiseSpec {
                    tile: m.tile.or(spec.tile),
                    ..m.clone()
                };
                s.noises[2 + 2 * i] = NoiseGpu::from_spec(&mask, size)?;
                s.transfers[2 + 2 * i] = transfer(&mask, &format!("layers[{i}].mask.transfer"))?;
            }
            s.layers[i] = StackLayerGpu {
                combine: l.combine.index(),
                weight: l.weight,
                _pad: [0; 2],
            };
        }
        Ok(s)
    }
}
