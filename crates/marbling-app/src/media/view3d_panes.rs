//! The 3D view's GPU side: the exact pipeline, one 3D renderer and target per pane
//! (registered with egui as textures), the uploaded design; frames are drawn only when
//! what they show changed ([`Drawn`]).

use crate::gpu::canvas_gpu::CANVAS_FORMAT;
use crate::media::view3d_recording::TurnRecording;
use eframe::egui_wgpu;
use marbling_core::Design;
use marbling_core::view3d::View3d;
use marbling_core::view3d::style::StyleFrame;
use marbling_gpu::{ExactRenderer, PendingRead, PreparedDesign, RenderTarget, View3dRenderer};

/// What one frame was drawn for (a new frame is drawn when it changes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drawn {
    /// The design's key.
    pub design_key: u64,
    /// The exact pane's view.
    pub view: View3d,
    /// Whether the texture comparison shows beside it.
    pub compare: bool,
    /// The style field's revision (`StyleControls::revision`).
    pub style: u64,
}

/// The panes' GPU resources.
pub struct Panes {
    exact: ExactRenderer,
    renderers: [View3dRenderer; 2],
    targets: [RenderTarget; 2],
    textures: [egui::TextureId; 2],
    prepared: Option<(u64, PreparedDesign)>,
    /// The design key the comparison's texture was baked from.
    baked: Option<u64>,
    drawn: Option<Drawn>,
}

impl Panes {
    /// The panes' textures for `size` pixels, (re)made in `slot` when the size changes.
    pub fn ensure(
        slot: &mut Option<Self>,
        rs: &egui_wgpu::RenderState,
        size: [u32; 2],
    ) -> [egui::TextureId; 2] {
        let device = &rs.device;
        let new_targets =
            || [0, 1].map(|_| RenderTarget::new(device, size[0], size[1], CANVAS_FORMAT));
        match slot {
            Some(p) if [p.targets[0].width, p.targets[0].height] == size => {}
            Some(p) => {
                p.targets = new_targets();
                let mut renderer = rs.renderer.write();
                for (t, id) in p.targets.iter().zip(p.textures) {
                    renderer.update_egui_texture_from_wgpu_texture(
                        device,
                        &t.view,
                        wgpu::FilterMode::Linear,
                        id,
                    );
                }
                p.drawn = None;
            }
            None => {
                let targets = new_targets();
                let mut renderer = rs.renderer.write();
                let textures = targets.each_ref().map(|t| {
                    renderer.register_native_texture(device, &t.view, wgpu::FilterMode::Linear)
                });
                let exact = ExactRenderer::new(device, CANVAS_FORMAT);
                let renderers = [0, 1].map(|_| View3dRenderer::new(device, &exact));
                *slot = Some(Self {
                    exact,
                    renderers,
                    targets,
                    textures,
                    prepared: None,
                    baked: None,
                    drawn: None,
                });
            }
        }
        slot.as_ref()
            .map_or([egui::TextureId::default(); 2], |p| p.textures)
    }

    /// Draws `views` (the exact pane's, then the comparison's) of `design` with the
    /// style's field blended in, unless the last frame was drawn for `now`; the exact
    /// pane's frame goes to a `recording` that has none on its way. True when drawn.
    pub fn draw(
        &mut self,
        rs: &egui_wgpu::RenderState,
        design: &Design,
        now: Drawn,
        views: &[View3d],
        style: Option<&StyleFrame>,
        recording: Option<&mut TurnRecording>,
    ) -> Result<bool, String> {
        if self.drawn == Some(now) {
            return Ok(false);
        }
        // Whatever comes of it, this frame is not tried again.
        self.drawn = Some(now);
        let (device, queue) = (&rs.device, &rs.queue);
        let prepared = match self.prepared.take() {
            Some((_, mut p)) => self
                .exact
                .update(device, queue, &mut p, design.into())
                .map(|()| p),
            None => self.exact.prepare(device, queue, design),
        };
        let mut prepared = prepared.map_err(|e| format!("cannot show the design in 3D: {e}"))?;
        let mut recording = recording.filter(|r| r.reading.is_none());
        for (i, view) in views.iter().enumerate() {
            if let Some(side) = view.texture
                && self.baked != Some(now.design_key)
            {
                self.renderers[i].bake(device, queue, &self.exact, &mut prepared, side);
                self.baked = Some(now.design_key);
            }
            self.renderers[i].set_style(device, queue, style);
            self.renderers[i].set_view(queue, &mut prepared, design, view);
            let mut encoder =
                device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
            {
                let mut pass = self.targets[i].begin_pass(&mut encoder);
                self.renderers[i].draw(device, &mut pass, &prepared);
            }
            match recording.take() {
                Some(r) if i == 0 => {
                    r.reading = Some(PendingRead::start(device, queue, encoder, &self.targets[0]));
                }
                _ => {
                    queue.submit([encoder.finish()]);
                }
            }
        }
        self.prepared = Some((now.design_key, prepared));
        Ok(true)
    }
}
