//! The playground app: state, what changes it, and the frame loop.

use crate::History;
use crate::action::{Action, Around};
use crate::automation::hooks::{Hooks, Seen};
use crate::frame::{Asked, with_frame};
use crate::gpu::canvas_gpu::CanvasGpu;
use crate::gpu::gpu_errors::GpuErrors;
use crate::gpu::recovery::{self, LostFlag, ParkedState};
use crate::marbling::canvas::Canvas;
use crate::marbling::editor::Editor;
use crate::platform;
use crate::shell::layout::SheetTab;
use crate::shell::message::Message;
use crate::shell::mode::Mode;
use crate::shell::sections::{self, Section};
use crate::state::{Panels, Rendering};
use crate::store::address_bar::AddressBar;
use crate::store::prefs::Prefs;
use crate::store::session::Session;
use crate::store::{autosave, restore};
use marbling_core::Design;

/// The marbling playground: the features it holds, each owning its state, and the
/// frame loop that lends them what they share; what changes the document is
/// [`Editor::apply`] (src/action.rs).
pub struct MarblingApp {
    /// The document being edited and how it is shown.
    pub(crate) editor: Editor,
    /// Tool, tool settings, palette, ink and antialiasing (kept in storage).
    pub(crate) prefs: Prefs,
    /// Autosave, recent designs and what is owed to storage.
    pub(crate) session: Session,
    /// The GPU renderer's side.
    pub(crate) rendering: Rendering,
    /// The automation hooks.
    pub(crate) hooks: Hooks,
    /// The panels' own state.
    pub(crate) panels: Panels,
    /// The noise playground: its settings and what is made from them.
    pub(crate) noise: crate::noise::Noise,
    /// The step player's speed, explain view and recording.
    pub(crate) player: crate::marbling::player::Player,
    /// The fragment the address bar holds.
    pub(crate) address: AddressBar,
}

impl MarblingApp {
    /// Creates the app: GPU resources, then the design from a share link, else the
    /// autosave, else the first gallery example.
    pub fn new(cc: &eframe::CreationContext<'_>) -> Self {
        crate::shell::style::apply(&cc.egui_ctx);
        let lost = LostFlag::default();
        let gpu_errors = GpuErrors::default();
        let mut gallery_texture = None;
        let (gpu, backend) = match &cc.wgpu_render_state {
            Some(rs) => {
                let gpu = CanvasGpu::new(&rs.device, rs.target_format);
                let gallery = crate::gpu::gallery_gpu::GalleryGpu::new(
                    &rs.device,
                    &rs.queue,
                    crate::gpu::canvas_gpu::SURROUND,
                );
                let mut renderer = rs.renderer.write();
                gallery_texture = Some(renderer.register_native_texture(
                    &rs.device,
                    gallery.view(),
                    wgpu::FilterMode::Linear,
                ));
                renderer.callback_resources.insert(gallery);
                renderer.callback_resources.insert(gpu);
                drop(renderer);
                lost.watch(&rs.device, &cc.egui_ctx);
                gpu_errors.watch(&rs.device, &cc.egui_ctx);
                platform::expose_device_loss(&rs.device);
                (
                    true,
                    crate::gpu::backend_name(rs.adapter.get_info().backend),
                )
            }
            None => (false, "none".to_owned()),
        };
        let fallback = crate::shell::gallery::entries()[0]
            .design()
            .unwrap_or_else(|_| {
                crate::store::file_panel::blank(crate::store::file_panel::NEW_SIZE)
            });
        let mut app = Self::with_design(fallback, backend, gpu);
        app.panels.gallery = crate::shell::landing::Gallery::with_gpu_texture(gallery_texture);
        app.editor.pristine = true;
        app.rendering.lost = lost;
        app.rendering.gpu_errors = gpu_errors;
        let adapter = cc
            .wgpu_render_state
            .as_ref()
            .map(|rs| rs.adapter.get_info());
        let switch = crate::fast_paint::Switch::from_flag(platform::query("fast_paint").as_deref());
        app.rendering.fast_paint = crate::fast_paint::FastPaint::new(switch, adapter.as_ref());
        autosave::flush_on_page_hide();
        // Starts listening for a pen's pressure before the first press.
        let _ = platform::pointer_pressure();
        platform::on_paste_image(app.panels.pictures.slot().clone(), cc.egui_ctx.clone());
        if let Some(parked) = recovery::take_parked() {
            app.unpark(parked);
            app.refresh();
            app.info("the GPU device was lost: the renderer was restarted, your work is kept");
            return app;
        }
        let stored = restore::read(|key| platform::load_string(cc.storage, key), &app.prefs);
        if let Some(r) = stored.autosave {
            app.editor.pristine = false;
            app.editor.history = History::new(r.design);
            autosave::unsaved().seq = r.seq;
        }
        for (text, why) in stored.unreadable {
            // Kept where no autosave overwrites it.
            if let Some(text) = text {
                app.session.keep(autosave::UNREADABLE_KEY, text);
            }
            app.error(format!(
                "the autosave could not be restored ({why}); its text is kept under {}",
                autosave::UNREADABLE_KEY
            ));
        }
        match stored.prefs {
            Some(Ok(p)) => app.prefs = p,
            Some(Err(e)) => log::warn!("{e}"),
            None => {}
        }
        if let Some(Err(e)) = stored.noise.map(|s| s.and_then(|s| app.noise.open(s))) {
            log::warn!("the stored noise setup was not restored: {e}");
        }
        app.session
            .restored(&app.prefs, app.noise.revision(), stored.recent);
        app.refresh();
        // A first visit (no link, no autosave) lands on the gallery; `?landing=0`
        // (automation) opens the first pattern instead. A link, good or broken, wins
        // over the landing (check_fragment).
        app.editor.landing =
            app.editor.pristine && platform::query("landing").as_deref() != Some("0");
        app.check_fragment();
        app
    }

    /// An app showing `design` (no window needed: used by tests too).
    pub fn with_design(design: Design, backend: String, gpu: bool) -> Self {
        Self {
            editor: Editor::new(design),
            prefs: Prefs::default(),
            session: Session::default(),
            rendering: Rendering::new(backend, gpu),
            hooks: Hooks::default(),
            panels: Panels::default(),
            noise: crate::noise::Noise::default(),
            player: Default::default(),
            address: AddressBar::default(),
        }
    }

    /// The editing state a restarted renderer must keep.
    fn park_state(&self) -> ParkedState {
        ParkedState {
            history: self.editor.history.clone(),
            prefs: self.prefs.clone(),
            last_fragment: self.address.fragment().map(str::to_owned),
        }
    }

    fn unpark(&mut self, p: ParkedState) {
        self.editor.history = p.history;
        self.prefs = p.prefs;
        self.address.remember(p.last_fragment);
    }

    /// Reacts to a lost GPU device once: parks the editing state for the restarted
    /// renderer (web) or says how to go on (native, where the autosave keeps the work).
    fn check_device_lost(&mut self) {
        if !self.rendering.lost.is_raised() || self.rendering.parked {
            return;
        }
        self.rendering.parked = true;
        self.panels.export.drop_png();
        // Written in this frame, whatever the debounce says.
        self.session.autosave_now();
        recovery::park(self.park_state());
        if cfg!(target_arch = "wasm32") {
            self.info("the GPU device was lost: restarting the renderer…");
        } else {
            self.error(
                "the GPU device was lost: your design is autosaved; restart the app to go on",
            );
        }
    }

    /// The shown design changed: new key, new snapshot (src/marbling/editor.rs).
    pub(crate) fn refresh(&mut self) {
        if let Err(e) = self.editor.refresh(&mut self.noise) {
            self.error(e);
        }
    }

    /// Carries out `action` (src/action.rs): the only place where the design and its
    /// history change.
    pub(crate) fn apply(&mut self, action: Action) {
        let around = Around {
            noise: &mut self.noise,
            session: &mut self.session,
            address: &mut self.address,
            panels: &mut self.panels,
            prefs: &self.prefs,
        };
        self.editor.apply(action, around);
    }

    /// In the noise playground: re-renders when a parameter or the zoom rule's factor
    /// changed.
    fn follow_noise(&mut self) {
        if self.editor.mode != Mode::Noise {
            return;
        }
        let factor = self.noise.factor_at(self.editor.view);
        if self.noise.follow(factor) {
            self.refresh();
        }
    }

    pub(crate) fn error(&mut self, text: impl Into<String>) {
        self.panels.message = Some(Message::error(text.into()));
    }

    pub(crate) fn info(&mut self, text: impl Into<String>) {
        self.panels.message = Some(Message::info(text.into()));
    }

    /// Opens what the address bar holds when it changed (src/store/address_bar.rs).
    pub(crate) fn check_fragment(&mut self) {
        with_frame!(self, |f| self.address.follow(&mut self.noise, &mut f));
    }

    /// Carries out what a feature asked for in its `ui` (src/frame.rs): its controls
    /// are listed, its actions applied in order, then its message shown.
    pub(crate) fn take_asked(&mut self, asked: Asked) {
        self.hooks.controls.extend(asked.controls);
        for action in asked.actions {
            self.apply(action);
        }
        if let Some(m) = asked.message {
            self.panels.message = Some(m);
        }
    }

    fn handle_shortcuts(&mut self, ctx: &egui::Context) {
        let pressed = crate::shell::shortcuts::read(ctx);
        for _ in 0..pressed.redos {
            self.apply(Action::Redo);
        }
        for _ in 0..pressed.undos {
            self.apply(Action::Undo);
        }
        if let Some(tool) = pressed.tool {
            self.prefs.tool = tool;
        }
    }

    fn advance_playback(&mut self, ctx: &egui::Context) {
        let Some(mut p) = self.editor.playback.filter(|p| p.playing) else {
            return;
        };
        let dt = f64::from(ctx.input(|i| i.stable_dt)).min(0.1);
        let steps = self.editor.history.design().gesture_sizes().len();
        let running = p.advance(dt, self.player.velocity(), steps);
        self.editor.playback = Some(p);
        self.refresh();
        if running {
            ctx.request_repaint();
        }
    }
    /// The canvas: its input first (a released gesture is applied at once, so the frame
    /// shows the design with it), then its picture (src/marbling/canvas.rs).
    fn canvas(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        let sense = egui::Sense::click_and_drag();
        let response = ui.allocate_exact_size(ui.available_size(), sense).1;
        let asked = self.canvas_parts().input(ui, &response);
        self.take_asked(asked);
        let drawn = self.canvas_parts().paint(ui, frame, &response);
        self.hooks.requested = drawn.requested;
        self.hooks.sheet_on_page = drawn.sheet_on_page;
        self.take_asked(drawn.asked);
    }

    fn canvas_parts(&mut self) -> Canvas<'_> {
        Canvas {
            editor: &mut self.editor,
            prefs: &mut self.prefs,
            noise: &mut self.noise,
            player: &mut self.player,
            midi: &mut self.panels.midi,
            sound: &self.panels.sound,
            rendering: &mut self.rendering,
        }
    }

    /// Shows the bottom sheet (the portrait layout's controls) as the lowest panel of `ui`
    /// (the whole window): its tabs, then the open tab's sections.
    fn bottom_sheet(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        self.panels.sheet.panel(ui).show(ui, |ui| {
            crate::shell::layout::touch_spacing(ui);
            with_frame!(self, |f| self.panels.sheet.tabs_ui(ui, &mut f));
            if let Some(tab) = self.panels.sheet.open_tab(self.editor.mode) {
                egui::ScrollArea::vertical()
                    .auto_shrink([false, false])
                    .show(ui, |ui| self.sections(ui, frame, Some(tab)));
            }
        });
    }

    /// The panel's sections for the mode, in order (`tab`: those of the bottom sheet's
    /// tab; on its Tools tab Undo and Redo come first, where a phone's user draws).
    fn sections(&mut self, ui: &mut egui::Ui, frame: &eframe::Frame, tab: Option<SheetTab>) {
        if tab == Some(SheetTab::Tools) {
            ui.horizontal(|ui| {
                with_frame!(self, |f| crate::marbling::history::panel::undo_redo_ui(
                    ui, &mut f
                ));
            });
        }
        for (section, rule) in sections::shown(self.editor.mode, tab) {
            if rule {
                ui.separator();
            }
            self.section(section, ui, frame);
        }
    }

    /// Draws one section of the panel.
    fn section(&mut self, section: Section, ui: &mut egui::Ui, frame: &eframe::Frame) {
        match section {
            Section::File => {
                let share = crate::store::file_panel::Sharing {
                    address: &mut self.address,
                    pictures: &mut self.panels.pictures,
                    qr: &mut self.panels.qr,
                };
                with_frame!(self, |f| self.panels.file.ui(ui, share, &mut f));
            }
            Section::Export => with_frame!(self, |f| self.panels.export.ui(
                ui,
                frame,
                &mut self.panels.print,
                &mut self.panels.view3d,
                &mut f
            )),
            Section::Noise => with_frame!(self, |f| self.noise.ui(ui, &mut f)),
            Section::Surface => {
                with_frame!(self, |f| crate::noise::panel::surface_ui(ui, &mut f));
            }
            Section::Tool => {
                with_frame!(self, |f| crate::marbling::tool_panel::ui(ui, &mut f));
                // Under the Flow tool, and under any other while it shows (its Stop).
                if self.prefs.tool == crate::marbling::tools::ToolKind::Flow
                    || self.rendering.stream.is_on()
                {
                    with_frame!(self, |f| self.rendering.stream.ui(ui, &mut f));
                }
            }
            Section::Ink => with_frame!(self, |f| self.panels.ink.ui(ui, &mut f)),
            Section::Picture => with_frame!(self, |f| self.panels.pictures.ui(ui, &mut f)),
            Section::Video => with_frame!(self, |f| self.rendering.video.ui(ui, &mut f)),
            Section::Midi => with_frame!(self, |f| self.panels.midi.ui(ui, &mut f)),
            Section::Sound => with_frame!(self, |f| self.panels.sound.ui(ui, &mut f)),
            Section::History => with_frame!(self, |f| self.panels.history.ui(ui, &mut f)),
            Section::Recent => {
                let recent = self.session.recent();
                with_frame!(self, |f| self.panels.recent.ui(ui, recent, &mut f));
            }
        }
    }
}

impl eframe::App for MarblingApp {
    /// The grey around the sheet: the canvas is drawn unfilled over it, and the canvas's
    /// paint callback draws only the sheet.
    fn clear_color(&self, _visuals: &egui::Visuals) -> [f32; 4] {
        let [r, g, b] = crate::gpu::canvas_gpu::SURROUND;
        egui::Color32::from_rgb(r, g, b).to_normalized_gamma_f32()
    }

    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        crate::automation::panic_guard::panic_if_requested();
        let ctx = ui.ctx().clone();
        // Mean interval of the last 60 frames, for the `data-frame-ms` hook.
        let dt = f64::from(ctx.input(|i| i.unstable_dt));
        self.hooks.count_frame(dt);
        if crate::gpu::device_pixels::fit_backing_store() {
            ctx.request_repaint();
        }
        self.check_device_lost();
        with_frame!(self, |f| self.panels.file.poll(&mut f));
        with_frame!(self, |f| self.panels.pictures.poll(&mut f));
        let pictures = self.panels.pictures.slot();
        crate::media::picture::route_dropped_files(&ctx, pictures, self.panels.file.slot());
        let drawn = self.rendering.status.lock().ok().and_then(|s| {
            let live = s.drawn.as_ref().and_then(|r| r.live.as_ref());
            live.map(|f| f.number)
        });
        with_frame!(self, |f| self.rendering.video.tick(&ctx, drawn, &mut f));
        let drawn = self.rendering.status.lock().ok().and_then(|s| {
            let stream = s.drawn.as_ref().and_then(|r| r.stream.as_ref());
            stream.map(|f| f.number)
        });
        let now = ctx.input(|i| i.time);
        with_frame!(self, |f| self.panels.sound.tick(&ctx, now, &mut f));
        let sound = &self.panels.sound;
        self.rendering.stream.drive(
            sound.factor(crate::media::sound::Target::StreamSpeed),
            sound.factor(crate::media::sound::Target::StreamStrength),
        );
        with_frame!(self, |f| self
            .rendering
            .stream
            .tick(&ctx, drawn, now, &mut f));
        with_frame!(self, |f| self.noise.poll_picked_data(&mut f));
        with_frame!(self, |f| self.panels.midi.tick(&ctx, &mut f));
        self.check_fragment();
        self.handle_shortcuts(&ctx);
        self.advance_playback(&ctx);
        with_frame!(self, |f| self.player.follow_recording(&ctx, &mut f));
        with_frame!(self, |f| self.panels.export.advance(frame, &ctx, &mut f));
        with_frame!(self, |f| self.noise.tick_export(&ctx, &mut f));
        self.follow_noise();
        self.hooks.controls.clear();
        // The window is cleared to the grey around the sheet and the canvas has no fill,
        // so no canvas pixel is drawn twice: on a software GPU each full-window fill costs
        // milliseconds a frame (docs/BENCHMARKS.md). The side panel's and status bar's
        // fills cost nothing while the panels are unchanged: they are part of the panels'
        // cached texture.
        let layer = ui.layer_id();
        let shape_count = || crate::fast_paint::FastPaint::mark(&ctx, layer);
        let panel_start = shape_count();
        // Phones and tablets get their own arrangement (src/shell/layout.rs); the gallery
        // takes the whole of a narrow screen (its cards open designs; "Back to the
        // editor" brings the controls back).
        let layout = crate::shell::layout::Layout::for_screen(
            ui.max_rect().size(),
            platform::touch_screen(),
        );
        self.panels.layout = layout;
        let narrow = ui.max_rect().width() < 720.0;
        let gallery_only = self.editor.landing && (narrow || layout.touch());
        let side_panel = match layout {
            _ if gallery_only => false,
            crate::shell::layout::Layout::Desktop => true,
            crate::shell::layout::Layout::Portrait => {
                self.bottom_sheet(ui, frame);
                false
            }
            crate::shell::layout::Layout::Landscape => {
                with_frame!(self, |frame| self.panels.rail.ui(ui, &mut frame));
                self.panels.rail.panel_open()
            }
        };
        if side_panel {
            // No margin under the scroll area: a control at the screen's bottom edge is
            // cut by the screen, never hidden in a band the scroll area does not show
            // (where `data-controls` would list it as if on screen).
            let mut panel_frame = egui::Frame::side_top_panel(ui.style());
            panel_frame.inner_margin.bottom = 0;
            egui::Panel::left("marbling_tools")
                .frame(panel_frame)
                .resizable(false)
                // The dark canvas marks the edge; a line would be one more draw call a
                // frame.
                .show_separator_line(false)
                .exact_size(crate::shell::layout::PANEL_WIDTH)
                .show(ui, |ui| {
                    if layout.touch() {
                        crate::shell::layout::touch_spacing(ui);
                    }
                    egui::ScrollArea::vertical().show(ui, |ui| {
                        with_frame!(self, |f| crate::shell::mode::switch_ui(ui, &mut f));
                        self.sections(ui, frame, None);
                    });
                });
        }
        let panel_end = shape_count();
        egui::Panel::bottom("marbling_status")
            .frame(egui::Frame::side_top_panel(ui.style()))
            .show_separator_line(false)
            .show(ui, |ui| {
                let line = crate::shell::status_bar::Line {
                    message: &mut self.panels.message,
                    zoom_to: &mut self.panels.zoom_to,
                    rendering: &self.rendering,
                    noise: &self.noise,
                };
                let said = with_frame!(self, |f| crate::shell::status_bar::ui(ui, line, &mut f));
                self.hooks.status = said;
            });
        let clear_color = eframe::App::clear_color(self, &ctx.global_style().visuals);
        self.rendering.fast_paint.panels(
            &ctx,
            frame.wgpu_render_state().map(Into::into),
            layer,
            &[panel_start..panel_end, panel_end..shape_count()],
            clear_color,
        );
        if self.editor.playback.is_some()
            && self.editor.mode == Mode::Marbling
            && !self.editor.landing
        {
            // The player takes at most what leaves the canvas 40 % of the screen's height
            // (less the player's and the canvas's margins, 32 points).
            let room =
                ui.available_rect_before_wrap().height() - 0.4 * ctx.content_rect().height() - 32.0;
            egui::Panel::bottom("marbling_player")
                .frame(egui::Frame::side_top_panel(ui.style()))
                .show_separator_line(false)
                .show(ui, |ui| {
                    with_frame!(self, |f| self.player.ui(ui, room, &mut f))
                });
        }
        // Set again by the canvas when it is shown this frame (src/automation/hooks.rs).
        self.hooks.requested = None;
        egui::CentralPanel::default()
            .frame(egui::Frame::central_panel(ui.style()).fill(egui::Color32::TRANSPARENT))
            .show(ui, |ui| {
                if self.editor.landing && self.editor.mode == Mode::Marbling {
                    let gpu = self.rendering.gpu;
                    with_frame!(self, |f| self.panels.gallery.ui(ui, gpu, &mut f));
                } else {
                    self.canvas(ui, frame);
                }
            });
        if let Some(e) = self
            .rendering
            .status
            .lock()
            .ok()
            .and_then(|s| s.error.clone())
            && self.panels.message.as_ref().is_none_or(|m| m.text != e)
        {
            self.error(e);
        }
        for e in self.rendering.gpu_errors.take() {
            self.error(e);
        }
        self.panels.view3d.show(
            &ctx,
            frame,
            self.editor.history.design(),
            self.editor.key,
            &mut self.hooks.controls,
        );
        with_frame!(self, |f| self.panels.qr.window_ui(&ctx, &mut f));
        let design = self.editor.history.design_shared();
        let noise = &self.noise;
        for e in self
            .session
            .write_owed(frame, &ctx, &self.prefs, noise, design)
        {
            self.error(e);
        }
        self.hooks.sample_memory(ctx.input(|i| i.time), frame);
        let seen = Seen {
            editor: &self.editor,
            prefs: &self.prefs,
            rendering: &self.rendering,
            panels: &self.panels,
            noise: &self.noise,
        };
        self.hooks.update(&ctx, seen);
    }

    /// Natively eframe calls this on exit: the waiting autosave is written.
    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        let mut u = autosave::unsaved();
        if self.session.owes_autosave() && u.design.is_none() {
            u.design = Some(self.editor.history.design_shared().clone());
        }
        u.flush(|key, value| {
            storage.set_string(key, value.to_owned());
            Ok(())
        });
    }
}
