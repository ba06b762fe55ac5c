//! The GPU renderer's side ([`Rendering`]) and the panels ([`Panels`]), shared by the
//! features the frame loop lends them to. The document is the marbling editor's
//! (`marbling::editor::Editor`), storage the session's (`store::session`), the hooks
//! automation's (`automation::hooks`), the tool preferences `store::prefs`'s.

use crate::gpu::canvas_gpu::CanvasStatus;
use crate::gpu::gpu_errors::GpuErrors;
use crate::gpu::recovery::LostFlag;
use crate::shell::message::Message;
use std::sync::{Arc, Mutex};

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
