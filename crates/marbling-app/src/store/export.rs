//! Export PNG (the panel that starts it is src/store/export_panel.rs): an
//! exact render of the design at a print size on the app's own GPU
//! device, read back tile by tile asynchronously (a browser cannot block on the GPU),
//! one tile in flight at a time, then PNG-encoded and handed to the user. Each tile is
//! drawn in parts over successive frames, as much a frame as keeps frames at
//! [`Pace::Idle`]'s interval (a [`FrameBudget`] like the canvas's), so no submission holds the GPU for
//! long and the page stays live.
//!
//! The pixels are those of `marbling render --backend gpu` at the same scale: the same
//! WGSL pass, sample positions and sRGB handling, so an export matches the CLI.

use crate::gpu::refine::{FrameBudget, Pace, Refinement, per_pixel};
use marbling_core::{Antialias, Design, RgbaImage, Window, output_size};
use marbling_gpu::{ExactRenderer, PendingRead, PreparedDesign, RenderTarget, View, tile_grid};

/// Format of the export tiles: the shader sRGB-encodes into it itself, like the CPU.
const EXPORT_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// Side of the tiles read back, pixels (each drawn in parts within the frame budget).
pub const EXPORT_TILE_SIDE: u32 = 1024;

/// The output sizes offered by Export PNG.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ExportSize {
    /// One output pixel per design pixel (the design's own size).
    Screen,
    /// Two output pixels per design pixel.
    Double,
    /// This many pixels wide, the height following the design's aspect ratio.
    Width(u32),
}

impl ExportSize {
    /// The choices shown in the panel, in order.
    pub const CHOICES: [ExportSize; 4] = [
        ExportSize::Screen,
        ExportSize::Double,
        ExportSize::Width(4096),
        ExportSize::Width(8192),
    ];

    /// The label shown in the panel.
    pub fn label(self) -> String {
        match self {
            ExportSize::Screen => "1×".to_owned(),
            ExportSize::Double => "2×".to_owned(),
            ExportSize::Width(w) => format!("{w} px"),
        }
    }

    /// The automation name of its radio button (`export-size-…` in `data-controls`).
    pub fn control_name(self) -> &'static str {
        match self {
            ExportSize::Screen => "export-size-1x",
            ExportSize::Double => "export-size-2x",
            ExportSize::Width(4096) => "export-size-4096",
            ExportSize::Width(8192) => "export-size-8192",
            ExportSize::Width(_) => "export-size-width",
        }
    }

    /// Output pixels per design pixel for `design`.
    pub fn scale(self, design: &Design) -> f64 {
        match self {
            ExportSize::Screen => 1.0,
            ExportSize::Double => 2.0,
            ExportSize::Width(w) => f64::from(w) / f64::from(design.width.max(1)),
        }
    }
}

/// What one [`PngExport::step`] achieved.
#[derive(Debug)]
pub enum ExportStep {
    /// Still rendering: `done` of `total` tiles are read back.
    Working {
        /// Tiles finished.
        done: usize,
        /// Tiles in all.
        total: usize,
    },
    /// Every tile is in; the image is complete.
    Finished(RgbaImage),
}

/// A tile of the output: x, y, width, height (pixels).
type Tile = (u32, u32, u32, u32);

/// A tile drawn and copied, waiting for its buffer to map.
struct InFlight {
    tile: Tile,
    read: PendingRead,
}

/// Longest side of an export in the app, pixels (the CLI streams any size).
pub const MAX_APP_EXPORT_SIDE: u32 = 16_384;
/// Most pixels of an export in the app: 512 MiB of RGBA held while it is encoded.
pub const MAX_APP_EXPORT_PIXELS: u64 = 128 * 1024 * 1024;

/// Whether an export of `width` × `height` px is within what the app holds
/// ([`MAX_APP_EXPORT_SIDE`], [`MAX_APP_EXPORT_PIXELS`]).
pub fn fits_in_app(width: u32, height: u32) -> bool {
    width.max(height) <= MAX_APP_EXPORT_SIDE
        && u64::from(width) * u64::from(height) <= MAX_APP_EXPORT_PIXELS
}

/// An export in progress.
pub struct PngExport {
    renderer: ExactRenderer,
    prepared: PreparedDesign,
    scale: f64,
    /// The window's top-left corner in output pixels from the design's origin (the
    /// view's offset of tile (0, 0); negative into a print's bleed).
    origin: [f64; 2],
    /// Pixels per metre written in the PNG's `pHYs` chunk (a print), if any.
    pixels_per_metre: Option<u32>,
    antialias: Antialias,
    tiles: Vec<Tile>,
    next: usize,
    /// The tile being drawn, its texture and the parts drawn so far.
    drawing: Option<(Tile, RenderTarget, Refinement)>,
    in_flight: Option<InFlight>,
    image: Option<RgbaImage>,
    budget: FrameBudget,
    /// When the last step drew, ms (the interval to the next steers the budget).
    last_draw_ms: Option<f64>,
    /// Parts drawn (submissions), for tests.
    parts: usize,
}

impl PngExport {
    /// Starts exporting `design` at `scale` on `device`; fails when the output is too
    /// large or the design does not fit the device.
    pub fn start(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        design: &Design,
        scale: f64,
        antialias: Antialias,
    ) -> Result<Self, String> {
        let (width, height) = output_size(design, scale).map_err(|e| e.to_string())?;
        let window = Window {
            x0: 0.0,
            y0: 0.0,
            scale,
            width,
            height,
        };
        Self::start_window(device, queue, design, &window, antialias)
    }

    /// Starts exporting `window` of `design` (a print, whose window reaches past the
    /// sheet into the bleed); fails past [`MAX_APP_EXPORT_SIDE`] or
    /// [`MAX_APP_EXPORT_PIXELS`], or when the design does not fit the device.
    pub fn start_window(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        design: &Design,
        window: &Window,
        antialias: Antialias,
    ) -> Result<Self, String> {
        window.check().map_err(|e| e.to_string())?;
        let (width, height, scale) = (window.width, window.height, window.scale);
        if !fits_in_app(width, height) {
            return Err(format!(
                "{width}×{height} px is more than the app can hold ({MAX_APP_EXPORT_SIDE} px on the long side, {} megapixels); the CLI streams any size: marbling render --print",
                MAX_APP_EXPORT_PIXELS / 1_000_000
            ));
        }
        let renderer = ExactRenderer::new(device, EXPORT_FORMAT);
        let prepared = renderer
            .prepare(device, queue, design)
            .map_err(|e| e.to_string())?;
        let side = EXPORT_TILE_SIDE.min(device.limits().max_texture_dimension_2d);
        Ok(Self {
            renderer,
            prepared,
            scale,
            origin: [window.x0 * scale, window.y0 * scale],
            pixels_per_metre: None,
            antialias,
            tiles: tile_grid(width, height, side),
            next: 0,
            drawing: None,
            in_flight: None,
            image: Some(RgbaImage::filled(width, height, [0, 0, 0, 255])),
            budget: FrameBudget::default(),
            last_draw_ms: None,
            parts: 0,
        })
    }

    /// Uses tiles of at most `side` × `side` pixels (call before the first step).
    pub fn with_tile_side(mut self, side: u32) -> Self {
        let (w, h) = self.size();
        self.tiles = tile_grid(w, h, side);
        self
    }

    /// Writes `ppm` pixels per metre into the PNG's `pHYs` chunk (a print's DPI).
    pub fn with_pixels_per_metre(mut self, ppm: u32) -> Self {
        self.pixels_per_metre = Some(ppm);
        self
    }

    /// The PNG of a finished export's `image`, carrying the DPI of a print.
    pub fn encode(&self, image: &RgbaImage) -> Result<Vec<u8>, String> {
        image
            .to_png_at(self.pixels_per_metre)
            .map_err(|e| e.to_string())
    }

    /// Output size, pixels.
    pub fn size(&self) -> (u32, u32) {
        self.image.as_ref().map_or((0, 0), |i| (i.width, i.height))
    }

    /// Submissions drawn so far (each a part of a tile within the frame budget).
    pub fn parts(&self) -> usize {
        self.parts
    }

    /// Advances the export without blocking: collects a tile whose read-back finished,
    /// draws the next part of the tile being drawn (or begins the next tile), and asks
    /// for a drawn tile to be read back. Call once per frame until it returns `Finished`.
    pub fn step(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
    ) -> Result<ExportStep, String> {
        // Native backends deliver map callbacks from `poll`; on the web it is a no-op.
        let _ = device.poll(wgpu::PollType::Poll);
        if let Some(flight) = &self.in_flight {
            let image = self.image.as_mut().ok_or("export state lost")?;
            let (x0, y0, _, _) = flight.tile;
            let row_bytes = image.width as usize * 4;
            // Each row of the tile into its place in the image.
            let outcome = flight.read.rows(|y, row| {
                let dst = (y0 + y) as usize * row_bytes + x0 as usize * 4;
                image.pixels[dst..dst + row.len()].copy_from_slice(row);
            });
            match outcome {
                None => return Ok(self.progress()),
                Some(Err(e)) => return Err(format!("reading the export back failed: {e}")),
                Some(Ok(())) => self.in_flight = None,
            }
        }
        if self.drawing.is_none() && self.next < self.tiles.len() {
            self.begin_tile(device, queue, self.tiles[self.next]);
            self.next += 1;
        }
        if self.drawing.is_some() {
            self.draw_part(device, queue);
            return Ok(self.progress());
        }
        self.image
            .take()
            .map(ExportStep::Finished)
            .ok_or_else(|| "the export has already finished".to_owned())
    }

    fn progress(&self) -> ExportStep {
        ExportStep::Working {
            done: self.next
                - usize::from(self.in_flight.is_some())
                - usize::from(self.drawing.is_some()),
            total: self.tiles.len(),
        }
    }

    /// Begins drawing `tile` into a texture of its own.
    fn begin_tile(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, tile: Tile) {
        let (x0, y0, w, h) = tile;
        self.prepared.set_view(
            queue,
            &View {
                scale: self.scale,
                offset: [
                    self.origin[0] + f64::from(x0),
                    self.origin[1] + f64::from(y0),
                ],
                antialias: self.antialias,
            },
        );
        let target = RenderTarget::new(device, w, h, EXPORT_FORMAT);
        self.drawing = Some((tile, target, Refinement::new([0, 0, w, h])));
    }

    /// Draws the next part of the tile being drawn, as large as this frame's budget;
    /// after its last part, copies the tile to a buffer and asks for it to be mapped.
    fn draw_part(&mut self, device: &wgpu::Device, queue: &wgpu::Queue) {
        let now = crate::platform::now_ms();
        if let Some(last) = self.last_draw_ms {
            self.budget.record_frame(now - last, Pace::Idle);
        }
        self.last_draw_ms = Some(now);
        let per = per_pixel(self.prepared.walk_cost(), self.antialias.samples().len());
        let pixels = (self.budget.units() / per).max(1);
        let Some((tile, target, refinement)) = &mut self.drawing else {
            return;
        };
        let mut encoder =
            device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
        if let Some(part) = refinement.next_tile(pixels) {
            let mut pass = target.begin_pass_keeping(&mut encoder);
            self.renderer.draw_rect(&mut pass, &self.prepared, part);
            self.parts += 1;
        }
        if !refinement.is_done() {
            queue.submit([encoder.finish()]);
            return;
        }
        let tile = *tile;
        let read = PendingRead::start(device, queue, encoder, target);
        self.drawing = None;
        self.in_flight = Some(InFlight { tile, read });
    }
}

/// The file name of an export: `marbling-<ops>ops-<w>x<h>.<ext>`.
pub fn export_file_name(design: &Design, size: (u32, u32), ext: &str) -> String {
    format!(
        "marbling-{}ops-{}x{}.{ext}",
        design.ops.len(),
        size.0,
        size.1
    )
}
