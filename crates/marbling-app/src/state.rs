//! The playground's shared state, in parts that change for different reasons (as the
//! egui demo structures its apps): the document being edited ([`Editor`]), the GPU
//! renderer's side ([`Rendering`]) and the panels ([`Panels`]). Features keep their own
//! state beside these: storage in `store::session`, the hooks in `automation::hooks`,
//! the tool preferences in `store::prefs`. Everything that changes the document goes
//! through `MarblingApp::apply` (src/action.rs).

use crate::History;
use crate::gpu::canvas_gpu::{CanvasStatus, StandIn};
use crate::gpu::gpu_errors::GpuErrors;
use crate::gpu::recovery::LostFlag;
use crate::marbling::canvas::ActiveGesture;
use crate::marbling::playback::Playback;
use crate::marbling::shown::Shown;
use crate::marbling::view::ViewState;
use crate::shell::message::Message;
use crate::shell::mode::Mode;
use marbling_core::{Design, ViewSpec};
use std::sync::{Arc, Mutex};

/// How many shown states [`Editor::recent`] remembers (the GPU holds the preview caches
/// of two).
pub const RECENT_STATES: usize = 4;

/// The document being edited and how it is shown: history, view, gesture, playback, and
/// the noise playground's parameters.
pub struct Editor {
    /// The design's history (the design is its current state).
    pub history: History,
    /// Bumped whenever the shown design changes (the GPU brings its upload up to date).
    pub key: u64,
    /// What may stand in for the shown design (`.0` = [`Self::key`]) while its exact
    /// frame is drawn: the design before the last edit, and the op the edit added.
    pub stand_in: Option<(u64, StandIn)>,
    /// The last few states shown, newest last, by key ([`RECENT_STATES`] at most): an
    /// Undo or Redo back to one of them has its preview cache stand in.
    pub recent: std::collections::VecDeque<(u64, Shown)>,
    /// The design on the canvas (the history, a viewed step or a playback frame).
    pub shown: Shown,
    /// `None` until the canvas size is known (then the design is fitted).
    pub view: Option<ViewState>,
    /// The last view made to fit the canvas, and the window and canvas it was made for
    /// (window width and height in points, physical pixels per point, canvas width and
    /// height in points): while `view` is still that one, a resized window, a changed
    /// pixel ratio or a canvas grown or shrunk by a panel fits it again.
    pub fit: Option<(ViewState, [f64; 5])>,
    /// A view asked for by a link's `v=` or the Zoom to box (centre and zoom), set on
    /// the canvas at its next layout.
    pub view_request: Option<ViewSpec>,
    /// The canvas's size at the last layout, points.
    pub canvas_size: [f64; 2],
    /// Two fingers are on the canvas: the view follows them unsnapped (snapping every
    /// frame would let the pinch's anchor drift), and is snapped when they lift.
    pub pinching: bool,
    /// The fingers on the canvas (src/marbling/fingers.rs).
    pub fingers: crate::marbling::fingers::Fingers,
    /// The tool being dragged.
    pub active: Option<ActiveGesture>,
    /// Seed of the next gesture's random choices.
    pub next_seed: u64,
    /// Play in progress.
    pub playback: Option<Playback>,
    /// True while the design is the start-up example nobody has touched (a link then
    /// replaces it instead of stacking on it).
    pub pristine: bool,
    /// The gallery is shown in place of the canvas (src/shell/landing.rs).
    pub landing: bool,
    /// Marbling or the noise playground.
    pub mode: Mode,
}

impl Editor {
    /// Editing `design`, fitted to the canvas on the first frame.
    pub fn new(design: Design) -> Self {
        let history = History::new(design);
        Self {
            shown: Shown::all(history.design_shared().clone()),
            history,
            key: 0,
            stand_in: None,
            recent: std::collections::VecDeque::new(),
            view: None,
            fit: None,
            view_request: None,
            canvas_size: [0.0; 2],
            pinching: false,
            fingers: Default::default(),
            active: None,
            next_seed: 1,
            playback: None,
            pristine: false,
            landing: false,
            mode: Mode::Marbling,
        }
    }

    /// Adds the state shown now to [`Self::recent`].
    pub fn remember_shown(&mut self) {
        self.recent.push_back((self.key, self.shown.clone()));
        if self.recent.len() > RECENT_STATES {
            self.recent.pop_front();
        }
    }

    /// The latest earlier state (key) that looks like the one shown now, if remembered.
    pub fn earlier_look_alike(&self) -> Option<u64> {
        self.recent
            .iter()
            .rev()
            .find(|(k, s)| *k != self.key && s.looks_like(&self.shown))
            .map(|(k, _)| *k)
    }
}

/// The GPU renderer's side: what the canvas reports back, device loss and errors, the
/// live preview's quality, a PNG export in progress.
pub struct Rendering {
    /// Shared with the canvas's paint callback.
    pub status: Arc<Mutex<CanvasStatus>>,
    /// `webgpu`, `webgl2`, or the native backend's name.
    pub backend: String,
    /// False when no wgpu render state exists (the canvas then says so).
    pub gpu: bool,
    /// Raised when the GPU device is lost.
    pub lost: LostFlag,
    /// GPU errors no error scope caught (shown instead of wgpu's panic).
    pub gpu_errors: GpuErrors,
    /// True once the state is parked for the renderer's restart.
    pub parked: bool,
    /// The software-GPU shortcuts and their switch (src/fast_paint/).
    pub fast_paint: crate::fast_paint::FastPaint,
    /// When the user last acted on the page (egui's clock, seconds): the canvas refines
    /// at its idle pace a while after.
    pub last_input_s: f64,
    /// The live video background (src/media/video_panel.rs).
    pub video: crate::media::video_panel::LiveVideoBackground,
    /// The design streaming along the Flow tool's noise (src/marbling/stream.rs).
    pub stream: crate::marbling::stream::FlowStream,
}

impl Rendering {
    /// The fraction of the exact frame drawn so far, while it is being drawn.
    pub fn progress(&self) -> Option<f64> {
        self.status.lock().ok().and_then(|s| s.progress)
    }

    /// A renderer on `backend` (`gpu`: whether a wgpu render state exists).
    pub fn new(backend: String, gpu: bool) -> Self {
        Self {
            status: Arc::default(),
            backend,
            gpu,
            lost: LostFlag::default(),
            gpu_errors: GpuErrors::default(),
            parked: false,
            fast_paint: Default::default(),
            last_input_s: 0.0,
            video: Default::default(),
            stream: Default::default(),
        }
    }
}

/// The panels' own state: the status line, file picks, thumbnails, the panel cache and
/// the sizes chosen for New and Export.
pub struct Panels {
    /// A line shown in the status bar; errors also go to `data-error`.
    pub message: Option<Message>,
    /// The status bar's Zoom to box (src/marbling/zoom_to.rs).
    pub zoom_to: crate::marbling::zoom_to::ZoomTo,
    /// The History section (src/marbling/history/panel.rs).
    pub history: crate::marbling::history::panel::HistoryPanel,
    /// The File section (src/store/file_panel.rs).
    pub file: crate::store::file_panel::FilePanel,
    /// Pictures as the background (src/media/picture.rs).
    pub pictures: crate::media::picture::Pictures,
    /// *Show QR* and its window (src/store/link_qr.rs).
    pub qr: crate::store::link_qr::LinkQrWindow,
    /// The gallery (src/shell/landing.rs).
    pub gallery: crate::shell::landing::Gallery,
    /// The *Recent designs* section (src/store/recent_panel.rs).
    pub recent: crate::store::recent_panel::RecentPanel,
    /// The Export section and the exports under way (src/store/export_panel.rs).
    pub export: crate::store::export_panel::ExportPanel,
    /// The Ink section and the palettes it imports (src/marbling/ink_panel.rs).
    pub ink: crate::marbling::ink_panel::InkPanel,
    /// *Print…*: the sheet, DPI and bleed of Export for print (src/store/print_panel.rs).
    pub print: crate::store::print_panel::PrintPanel,
    /// The 3D view window (src/media/view3d.rs).
    pub view3d: crate::media::view3d::View3dWindow,
    /// The portrait layout's bottom sheet (src/shell/bottom_sheet.rs).
    pub sheet: crate::shell::bottom_sheet::BottomSheet,
    /// The landscape layout's tool rail (src/shell/tool_rail.rs).
    pub rail: crate::shell::tool_rail::ToolRail,
    /// The layout of the last frame (for `data-layout`).
    pub layout: crate::shell::layout::Layout,
    /// MIDI in: notes make drops, controllers move parameters.
    pub midi: crate::media::midi::MidiPanel,
    /// Sound in: the bands' levels drive drops, the Stream and a stroke's pressure.
    pub sound: crate::media::sound::SoundPanel,
}

impl Default for Panels {
    fn default() -> Self {
        Self {
            message: None,
            zoom_to: Default::default(),
            history: Default::default(),
            file: Default::default(),
            pictures: Default::default(),
            qr: Default::default(),
            gallery: Default::default(),
            recent: Default::default(),
            export: Default::default(),
            print: Default::default(),
            ink: Default::default(),
            view3d: crate::media::view3d::View3dWindow::default(),
            sheet: Default::default(),
            rail: Default::default(),
            layout: crate::shell::layout::Layout::Desktop,
            midi: Default::default(),
            sound: Default::default(),
        }
    }
}
