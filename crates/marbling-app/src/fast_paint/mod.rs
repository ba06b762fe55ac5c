//! Fast paint: the shortcuts that make the app usable on a software GPU (SwiftShader, what
//! headless Chromium and GPU-less machines use; a weak integrated GPU), behind one switch.
//!
//! On such a device every pixel of every draw costs CPU time, and egui redraws every
//! shape each frame with a shader whose every branch runs for every pixel. Three
//! shortcuts cut that (measured in docs/BENCHMARKS.md):
//! - [`panel_cache`]: the side panel and status bar are copied from a texture while their
//!   shapes do not change;
//! - [`flat_overlay`] + [`flat_mesh`]: the tool overlay's untextured shapes are drawn by a
//!   straight-line shader instead of egui's;
//! - [`preview_quality`]: the live preview drops to one sample per pixel once a drag's
//!   frames come slower than 30 per second.
//!
//! [`layer_shapes`] is the egui-internal helper the first two share.
//!
//! **When.** On a real GPU they only cost time (the panel cache compares the panels'
//! shapes every frame), so [`FastPaint`] turns them on only where they pay: on a
//! software adapter (wgpu reports a CPU device, or its name says SwiftShader, llvmpipe or
//! lavapipe), or once the preview's frames were measured slow. The page's
//! `?fast_paint=on|off` forces it either way (tests); the hook `data-fast-paint` says
//! which it is and why.

pub(crate) mod flat_mesh;
pub(crate) mod flat_overlay;
pub(crate) mod layer_shapes;
pub(crate) mod panel_cache;
pub(crate) mod preview_quality;

use marbling_core::Antialias;
use panel_cache::{PanelCache, PanelGpu};
use preview_quality::PreviewQuality;
use std::ops::Range;

/// The page's choice (`?fast_paint=`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Switch {
    /// Decide from the adapter and the measured preview frames.
    #[default]
    Auto,
    /// Always (`on`).
    On,
    /// Never (`off`).
    Off,
}

impl Switch {
    /// The switch for the query value `flag` (`on`, `1`, `off`, `0`; anything else or
    /// nothing: automatic).
    pub fn from_flag(flag: Option<&str>) -> Self {
        match flag {
            Some("on" | "1") => Switch::On,
            Some("off" | "0") => Switch::Off,
            _ => Switch::Auto,
        }
    }
}

/// Whether an adapter renders in software.
pub fn is_software(info: &wgpu::AdapterInfo) -> bool {
    let name = format!("{} {}", info.name, info.driver).to_lowercase();
    info.device_type == wgpu::DeviceType::Cpu
        || ["swiftshader", "llvmpipe", "lavapipe"]
            .iter()
            .any(|s| name.contains(s))
}

/// The fast-paint shortcuts and the switch that decides whether they run.
#[derive(Default)]
pub struct FastPaint {
    switch: Switch,
    software_adapter: bool,
    panels: PanelCache,
    preview: PreviewQuality,
}

impl FastPaint {
    /// For the page's `switch` and the adapter the app draws with (`None`: no GPU).
    pub fn new(switch: Switch, adapter: Option<&wgpu::AdapterInfo>) -> Self {
        Self {
            switch,
            software_adapter: adapter.is_some_and(is_software),
            ..Self::default()
        }
    }

    /// Why the shortcuts run, or `None` when they do not.
    pub fn reason(&self) -> Option<&'static str> {
        match self.switch {
            Switch::On => Some("flag"),
            Switch::Off => None,
            Switch::Auto if self.software_adapter => Some("software adapter"),
            Switch::Auto if self.preview.reduced() => Some("slow frames"),
            Switch::Auto => None,
        }
    }

    /// True when the shortcuts run.
    pub fn on(&self) -> bool {
        self.reason().is_some()
    }

    /// The `data-fast-paint` hook: `off`, or `on (` the reason `)`.
    pub fn hook(&self) -> String {
        self.reason()
            .map_or_else(|| "off".to_owned(), |why| format!("on ({why})"))
    }

    /// How many shapes `layer` holds so far this pass: marks where a panel or overlay
    /// starts and ends.
    pub fn mark(ctx: &egui::Context, layer: egui::LayerId) -> usize {
        layer_shapes::count(ctx, layer)
    }

    /// The panels just painted (`panels`: ranges of `layer`'s shapes) drawn from the
    /// panel cache while unchanged ([`PanelCache::substitute`]); nothing when off.
    pub fn panels(
        &mut self,
        ctx: &egui::Context,
        gpu: Option<PanelGpu<'_>>,
        layer: egui::LayerId,
        panels: &[Range<usize>],
        clear_color: [f32; 4],
    ) {
        if self.on() {
            self.panels.substitute(ctx, gpu, layer, panels, clear_color);
        }
    }

    /// The overlay's shapes (`range` of `layer`) drawn by the flat-mesh pipeline
    /// ([`flat_overlay::substitute`]); nothing when off. True when substituted.
    pub fn overlay(
        &self,
        ctx: &egui::Context,
        target_format: Option<wgpu::TextureFormat>,
        layer: egui::LayerId,
        range: Range<usize>,
    ) -> bool {
        self.on() && flat_overlay::substitute(ctx, target_format, layer, range)
    }

    /// Records a live-preview frame that took `interval_s` with `samples` per pixel.
    pub fn preview_frame(&mut self, interval_s: f64, samples: usize) {
        if self.switch != Switch::Off {
            self.preview.record(interval_s, samples);
        }
    }

    /// A drag ended (the next is measured afresh).
    pub fn end_drag(&mut self) {
        self.preview.end_drag();
    }

    /// The live preview's antialiasing for the user's choice.
    pub fn preview_antialias(&self, chosen: Antialias) -> Antialias {
        if self.switch == Switch::Off {
            chosen
        } else {
            self.preview.antialias(chosen)
        }
    }

    /// True once the preview takes one sample per pixel.
    pub fn preview_reduced(&self) -> bool {
        self.switch != Switch::Off && self.preview.reduced()
    }

    /// Frames the panels were copied from the cache, and renders into it.
    pub fn panel_counts(&self) -> (u64, u64) {
        (self.panels.copies, self.panels.renders)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn adapter(name: &str, device_type: wgpu::DeviceType) -> wgpu::AdapterInfo {
        wgpu::AdapterInfo {
            name: name.to_owned(),
            ..wgpu::AdapterInfo::new(device_type, wgpu::Backend::Gl)
        }
    }

    #[test]
    fn software_adapters_are_recognised() {
        let cpu = adapter("", wgpu::DeviceType::Cpu);
        let angle = adapter(
            "ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero)), SwiftShader driver)",
            wgpu::DeviceType::Other,
        );
        let lavapipe = adapter("llvmpipe (LLVM 19.1.7, 256 bits)", wgpu::DeviceType::Other);
        let nvidia = adapter("NVIDIA H200", wgpu::DeviceType::DiscreteGpu);
        assert!(is_software(&cpu) && is_software(&angle) && is_software(&lavapipe));
        assert!(!is_software(&nvidia));
    }

    #[test]
    fn the_switch_decides_and_says_why() {
        let nvidia = adapter("NVIDIA H200", wgpu::DeviceType::DiscreteGpu);
        let swiftshader = adapter("SwiftShader Device", wgpu::DeviceType::Other);
        let auto = Switch::from_flag(None);
        assert_eq!(FastPaint::new(auto, Some(&nvidia)).hook(), "off");
        assert_eq!(
            FastPaint::new(auto, Some(&swiftshader)).hook(),
            "on (software adapter)"
        );
        assert_eq!(
            FastPaint::new(Switch::from_flag(Some("on")), Some(&nvidia)).hook(),
            "on (flag)"
        );
        let off = FastPaint::new(Switch::from_flag(Some("off")), Some(&swiftshader));
        assert!(!off.on());
        assert_eq!(Switch::from_flag(Some("maybe")), Switch::Auto);
    }

    #[test]
    fn slow_preview_frames_turn_it_on_unless_switched_off() {
        let nvidia = adapter("NVIDIA H200", wgpu::DeviceType::DiscreteGpu);
        for (switch, reduced) in [(Switch::Auto, true), (Switch::Off, false)] {
            let mut fast = FastPaint::new(switch, Some(&nvidia));
            for _ in 0..preview_quality::FRAMES_TO_DECIDE {
                fast.preview_frame(0.1, 4);
            }
            assert_eq!(fast.preview_reduced(), reduced, "{switch:?}");
            assert_eq!(fast.on(), reduced, "{switch:?}");
            let expected = if reduced {
                Antialias::None
            } else {
                Antialias::Rgss
            };
            assert_eq!(fast.preview_antialias(Antialias::Rgss), expected);
        }
        let mut fast = FastPaint::new(Switch::Auto, Some(&nvidia));
        for _ in 0..preview_quality::FRAMES_TO_DECIDE {
            fast.preview_frame(0.005, 4);
        }
        assert_eq!(fast.hook(), "off", "200 frames a second need no shortcut");
    }
}
