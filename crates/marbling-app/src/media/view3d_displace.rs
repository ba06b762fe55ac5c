//! The 3D view's *Displace* row (Kung 2019, ch. 3): the object's surface moved along its
//! normals by Perlin fBm — amount, bump frequency and octaves — and *Flow*, which
//! animates the noise's offset so the bumps travel up the object.

use crate::media::step_clock::StepClock;
use marbling_core::view3d::Displace;
use marbling_core::view3d::displace::{AMOUNT, FREQUENCY, OCTAVES};

/// How fast *Flow* moves the noise's offset, object units per second (the sphere's
/// radius is 1).
pub const FLOW_SPEED: f64 = 0.3;

/// The displacement the 3D view draws and whether it flows.
#[derive(Debug, Default)]
pub struct DisplaceControls {
    /// The displacement (amount 0: none).
    pub displace: Displace,
    /// Whether the offset moves with time.
    pub flowing: bool,
    /// The flow's clock.
    clock: StepClock,
}

impl DisplaceControls {
    /// The row of controls; names them in `controls` for automation.
    pub fn ui(
        &mut self,
        ui: &mut egui::Ui,
        controls: &mut Vec<(std::borrow::Cow<'static, str>, egui::Rect)>,
    ) {
        let d = &mut self.displace;
        ui.horizontal_wrapped(|ui| {
            let r = ui
                .add(egui::Slider::new(&mut d.amount, AMOUNT).text("displace"))
                .on_hover_text(
                    "Moves the surface along its normals by Perlin noise (Kung 2019), in \
                     object units: the sphere's radius is 1",
                );
            controls.push(("view3d-displace".into(), r.rect));
        });
        // One slider a row: a phone's width holds one slider beside a button, not two.
        ui.horizontal_wrapped(|ui| {
            let r = ui
                .add(egui::Slider::new(&mut d.frequency, FREQUENCY).text("bumps"))
                .on_hover_text("The noise's frequency: lattice cells per object unit");
            controls.push(("view3d-displace-frequency".into(), r.rect));
        });
        ui.horizontal_wrapped(|ui| {
            let r = ui
                .add(egui::Slider::new(&mut d.octaves, OCTAVES).text("octaves"))
                .on_hover_text("Octaves of the fBm: each adds bumps twice as fine, half as high");
            controls.push(("view3d-displace-octaves".into(), r.rect));
            let r = ui
                .add_enabled(
                    d.is_active(),
                    egui::Button::new("Flow").selected(self.flowing),
                )
                .on_hover_text("Moves the noise with time: the bumps travel up the object");
            controls.push(("view3d-displace-flow".into(), r.rect));
            if r.clicked() {
                self.flowing = !self.flowing;
            }
        });
    }

    /// Moves the offset by the time passed since the last frame ([`StepClock`]); true
    /// while it flows.
    pub fn step(&mut self, ctx: &egui::Context) -> bool {
        if !(self.flowing && self.displace.is_active()) {
            self.clock.stop();
            return false;
        }
        let dt = self.clock.step();
        // Down the noise, so the bumps rise; wrapped far from f32's limits.
        self.displace.offset[1] = (self.displace.offset[1] - FLOW_SPEED * dt).rem_euclid(1.0e4);
        ctx.request_repaint();
        true
    }

    /// The `displace` member of the `data-view3d` hook.
    pub fn hook(&self) -> serde_json::Value {
        let d = &self.displace;
        serde_json::json!({
            "amount": d.amount,
            "frequency": d.frequency,
            "octaves": d.octaves,
            "flowing": self.flowing,
            "offset": d.offset,
        })
    }
}
