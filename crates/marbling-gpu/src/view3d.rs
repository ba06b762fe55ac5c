//! The 3D view on the GPU (shaders/view3d.wgsl, appended to the exact renderer's
//! module): the twin of `marbling_core::view3d`, every sample's ray meeting the object
//! and its design point walked back through every op in the fragment shader. Bind
//! group 0 is the design's ([`PreparedDesign`]), group 1 the camera, the optional
//! baked texture of the "as a texture" comparison and the optional style field
//! (`marbling_core::view3d::style::StyleFrame::field`), blended into each pixel as the
//! CPU's `StyleFrame::composite` does.

use crate::bindings;
use crate::exact::{ExactRenderer, PreparedDesign, View};
use crate::shaders::ExactVariant;
use crate::target::RenderTarget;
use crate::variants::Variants;
use marbling_core::view3d::style::StyleFrame;
use marbling_core::view3d::{
    AMBIENT, BACKDROP, BOOK_DEPTH, INSIDE_SHADE, PAGES, SPINE_SHADE, VASE_BISECTIONS, VASE_BOUND,
    VASE_STEPS, Vec3, View3d, displace,
};
use marbling_core::{Design, Rgb8};
use marbling_noise::StyleBlend;

/// `shaders/view3d.wgsl`.
pub const VIEW3D: &str = include_str!("../shaders/view3d.wgsl");

/// The 3D module of an exact-renderer variant.
/// The render module holds the noise lattice (hash, Perlin) or gets it here for the
/// displacement's 3D Perlin noise.
pub fn view3d_wgsl(variant: ExactVariant) -> String {
    let noise3 = if variant.has_noise_lattice() {
        marbling_noise::wgsl::PERLIN3.to_owned()
    } else {
        marbling_noise::wgsl::module("perlin3")
            .unwrap_or_else(|| unreachable!("marbling-noise always provides perlin3"))
    };
    [variant.render_wgsl(), noise3, VIEW3D.to_owned()].join("\n")
}

/// The camera and object of one frame. Keep in sync with `struct View3dParams` in
/// shaders/view3d.wgsl (checked by tests/it/layout.rs).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct View3dParams {
    /// Camera position (w unused).
    pub origin: [f32; 4],
    /// Unit forward.
    pub forward: [f32; 4],
    /// Unit right.
    pub right: [f32; 4],
    /// Unit up.
    pub up: [f32; 4],
    /// tan(fov/2), aspect W/H, shape code, source (0 exact; 1 baked, linear on load;
    /// 2 baked, sRGB-encoded).
    pub lens: [f32; 4],
    /// Frame width, height (output pixels), design width, height.
    pub frame: [f32; 4],
    /// Linear paper colour.
    pub paper: [f32; 4],
    /// Linear pages colour.
    pub pages: [f32; 4],
    /// Linear backdrop colour at the top.
    pub backdrop_top: [f32; 4],
    /// Linear backdrop colour at the bottom.
    pub backdrop_bottom: [f32; 4],
    /// Ambient share, spine shade, inside shade, book half-depth.
    pub shading: [f32; 4],
    /// Vase bound radius, march steps, bisection steps, cylinder half-height.
    pub shape: [f32; 4],
    /// Displacement: amplitude s (0: none), frequency f, octaves, lacunarity.
    pub displace: [f32; 4],
    /// Displacement: persistence, offset o (x, y, z).
    pub displace_fbm: [f32; 4],
    /// The displaced march: what its bounding volume adds to the object's extent
    /// (s·bound + margin), steps, bisection steps, the normal's finite-difference step.
    pub displace_march: [f32; 4],
    /// The style's blend (0: none, 1: ink, 2: multiply, 3: overlay; see
    /// `marbling_noise::StyleBlend`), the rest unused.
    pub style: [f32; 4],
    /// The style's ink, sRGB in [0, 1] (w unused).
    pub style_ink: [f32; 4],
}

fn v4(v: Vec3) -> [f32; 4] {
    [v.x as f32, v.y as f32, v.z as f32, 0.0]
}

fn rgb4(c: Rgb8) -> [f32; 4] {
    let [r, g, b] = c.to_linear();
    [r, g, b, 1.0]
}

impl View3dParams {
    /// The parameters of `view` of `design`; `source` as in [`View3dParams::lens`].
    pub fn new(design: &Design, view: &View3d, source: u32) -> Self {
        let rig = view.rig(design);
        let object = view.object(design);
        let d = view.displace;
        Self {
            origin: v4(rig.origin),
            forward: v4(rig.forward),
            right: v4(rig.right),
            up: v4(rig.up),
            lens: [
                rig.tan_half as f32,
                object.aspect as f32,
                view.shape.code() as f32,
                source as f32,
            ],
            frame: [
                view.width as f32,
                view.height as f32,
                design.width as f32,
                design.height as f32,
            ],
            paper: rgb4(design.background),
            pages: rgb4(Rgb8::new(PAGES[0], PAGES[1], PAGES[2])),
            backdrop_top: rgb4(BACKDROP[0]),
            backdrop_bottom: rgb4(BACKDROP[1]),
            shading: [AMBIENT as f32, SPINE_SHADE, INSIDE_SHADE, BOOK_DEPTH as f32],
            shape: [
                VASE_BOUND as f32,
                VASE_STEPS as f32,
                VASE_BISECTIONS as f32,
                object.cylinder_half_height() as f32,
            ],
            displace: [
                d.amount as f32,
                d.frequency as f32,
                d.octaves as f32,
                d.lacunarity as f32,
            ],
            displace_fbm: [
                d.persistence as f32,
                d.offset[0] as f32,
                d.offset[1] as f32,
                d.offset[2] as f32,
            ],
            displace_march: [
                (d.reach() + displace::BOUND_MARGIN) as f32,
                displace::DISPLACE_STEPS as f32,
                displace::DISPLACE_BISECTIONS as f32,
                displace::NORMAL_STEP as f32,
            ],
            style: [0.0; 4],
            style_ink: [0.0; 4],
        }
    }
}

/// The `style` code of a blend in [`View3dParams::style`].
fn blend_code(blend: StyleBlend) -> f32 {
    match blend {
        StyleBlend::Ink => 1.0,
        StyleBlend::Multiply => 2.0,
        StyleBlend::Overlay => 3.0,
    }
}

/// Draws 3D views of prepared designs into targets of the exact renderer's format.
#[derive(Debug)]
pub struct View3dRenderer {
    layout: wgpu::BindGroupLayout,
    pipeline_layout: wgpu::PipelineLayout,
    /// One per [`ExactVariant`], built on first use.
    pipelines: Variants<wgpu::RenderPipeline>,
    format: wgpu::TextureFormat,
    uniform: wgpu::Buffer,
    params: Option<View3dParams>,
    /// The baked design of the texture comparison (1×1 when off).
    baked: RenderTarget,
    /// The style field (1×1 when there is none) and the blend and ink it goes with.
    style_field: wgpu::Texture,
    style: ([f32; 4], [f32; 4]),
    bind_group: wgpu::BindGroup,
}

impl View3dRenderer {
    /// A renderer next to `exact` (whose bind group layout it shares as group 0).
    pub fn new(device: &wgpu::Device, exact: &ExactRenderer) -> Self {
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("marbling 3d view"),
            entries: &[
                bindings::uniform::<View3dParams>(0, wgpu::ShaderStages::FRAGMENT),
                bindings::texture_2d(1, wgpu::ShaderStages::FRAGMENT, false),
                bindings::texture_2d(2, wgpu::ShaderStages::FRAGMENT, false),
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("marbling 3d view"),
            bind_group_layouts: &[Some(exact.bind_group_layout()), Some(&layout)],
            immediate_size: 0,
        });
        let uniform = bindings::uniform_buffer::<View3dParams>(device, "marbling 3d view");
        let baked = RenderTarget::new(device, 1, 1, exact.format());
        let style_field = field_texture(device, 1, 1);
        let bind_group = Self::group(device, &layout, &uniform, &baked, &style_field);
        Self {
            layout,
            pipeline_layout,
            pipelines: Default::default(),
            format: exact.format(),
            uniform,
            params: None,
            baked,
            style_field,
            style: ([0.0; 4], [0.0; 4]),
            bind_group,
        }
    }

    /// Remakes the bind group after a texture of it was replaced.
    fn rebind(&mut self, device: &wgpu::Device) {
        self.bind_group = Self::group(
            device,
            &self.layout,
            &self.uniform,
            &self.baked,
            &self.style_field,
        );
    }

    fn group(
        device: &wgpu::Device,
        layout: &wgpu::BindGroupLayout,
        uniform: &wgpu::Buffer,
        baked: &RenderTarget,
        style_field: &wgpu::Texture,
    ) -> wgpu::BindGroup {
        let field = style_field.create_view(&wgpu::TextureViewDescriptor::default());
        crate::bindings::bind_group(
            device,
            "marbling 3d view",
            layout,
            &[
                uniform.as_entire_binding(),
                wgpu::BindingResource::TextureView(&baked.view),
                wgpu::BindingResource::TextureView(&field),
            ],
        )
    }

    /// Sets the style blended into the next draws (`None`: no style): `frame` must have
    /// the view's size. Takes effect at the next [`View3dRenderer::set_view`].
    pub fn set_style(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        frame: Option<&StyleFrame>,
    ) {
        let Some(frame) = frame else {
            self.style = ([0.0; 4], [0.0; 4]);
            return;
        };
        let size = self.style_field.size();
        if (size.width, size.height) != (frame.width, frame.height) {
            self.style_field = field_texture(device, frame.width, frame.height);
            self.rebind(device);
        }
        queue.write_texture(
            self.style_field.as_image_copy(),
            &frame.field(),
            wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(frame.width * 4),
                rows_per_image: Some(frame.height),
            },
            self.style_field.size(),
        );
        let [r, g, b] = frame.ink_unit();
        self.style = ([blend_code(frame.blend), 0.0, 0.0, 0.0], [r, g, b, 0.0]);
    }

    /// Bakes `design` (uploaded as `prepared`) into a raster of longest side `side`
    /// with `exact`, for views with `texture: Some(side)` (the comparison with texture
    /// mapping). Leaves `prepared`'s view to [`View3dRenderer::set_view`].
    pub fn bake(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        exact: &ExactRenderer,
        prepared: &mut PreparedDesign,
        side: u32,
    ) {
        let (dw, dh) = prepared.design_size();
        let k = f64::from(side) / f64::from(dw.max(dh));
        let w = ((f64::from(dw) * k).round() as u32).clamp(1, side);
        let h = ((f64::from(dh) * k).round() as u32).clamp(1, side);
        if (self.baked.width, self.baked.height) != (w, h) {
            self.baked = RenderTarget::new(device, w, h, self.format);
            self.rebind(device);
        }
        prepared.set_view(
            queue,
            &View {
                scale: k,
                offset: [0.0; 2],
                antialias: marbling_core::Antialias::Rgss,
            },
        );
        let mut encoder =
            device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
        {
            let mut pass = self.baked.begin_pass(&mut encoder);
            exact.draw(&mut pass, prepared);
        }
        queue.submit([encoder.finish()]);
    }

    /// Sets the view of the next draws of `prepared` (holding `design`): the camera,
    /// object and antialiasing of `view`; with `view.texture` set, the draws sample the
    /// raster of the last [`View3dRenderer::bake`] instead of walking the ops. Applies
    /// to command buffers submitted afterwards.
    pub fn set_view(
        &mut self,
        queue: &wgpu::Queue,
        prepared: &mut PreparedDesign,
        design: &Design,
        view: &View3d,
    ) {
        let source = match (view.texture, self.format.is_srgb()) {
            (None, _) => 0,
            (Some(_), true) => 1,
            (Some(_), false) => 2,
        };
        prepared.set_view(
            queue,
            &View {
                scale: 1.0,
                offset: [0.0; 2],
                antialias: view.antialias,
            },
        );
        let params = View3dParams {
            style: self.style.0,
            style_ink: self.style.1,
            ..View3dParams::new(design, view, source)
        };
        if self.params != Some(params) {
            queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&params));
            self.params = Some(params);
        }
    }

    /// Records a draw of `prepared` (its view set by [`View3dRenderer::set_view`]) into
    /// `pass`, whose target has the exact renderer's format and the view's size.
    pub fn draw(
        &self,
        device: &wgpu::Device,
        pass: &mut wgpu::RenderPass<'_>,
        prepared: &PreparedDesign,
    ) {
        let variant = prepared.variant();
        let pipeline = self.pipelines.get_or_init(variant, || {
            let label = format!("marbling 3d view ({})", variant.name());
            let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some(&label),
                source: wgpu::ShaderSource::Wgsl(view3d_wgsl(variant).into()),
            });
            crate::fullscreen::pipeline_with(
                device,
                &label,
                &self.pipeline_layout,
                &module,
                ["vs_main", "fs_view3d"],
                self.format,
            )
        });
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, prepared.bind_group(), &[]);
        pass.set_bind_group(1, &self.bind_group, &[]);
        pass.draw(0..3, 0..1);
    }
}

/// A style field texture of `width`×`height` texels (read with `textureLoad`).
fn field_texture(device: &wgpu::Device, width: u32, height: u32) -> wgpu::Texture {
    bindings::written_texture(
        device,
        "marbling 3d style field",
        width,
        height,
        wgpu::TextureFormat::Rgba8Unorm,
    )
}
