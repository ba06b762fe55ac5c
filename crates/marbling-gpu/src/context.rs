//! A wgpu device and queue to render with: opened headless on any adapter (a GPU, or a
//! CPU implementation such as Mesa's lavapipe), or handed in by an app that owns its own.

use crate::GpuError;

/// A device, its queue, and what the adapter is.
#[derive(Clone, Debug)]
pub struct GpuContext {
    /// The device pipelines and textures are created on.
    pub device: wgpu::Device,
    /// Its queue.
    pub queue: wgpu::Queue,
    /// The adapter's name, backend and type.
    pub info: wgpu::AdapterInfo,
}

impl GpuContext {
    /// Wraps a device the caller already owns (e.g. the app's egui_wgpu device).
    pub fn from_parts(device: wgpu::Device, queue: wgpu::Queue, info: wgpu::AdapterInfo) -> Self {
        Self {
            device,
            queue,
            info,
        }
    }

    /// Opens a device on the best adapter available: a high-performance GPU if there is
    /// one, else the fallback (CPU) adapter, else any adapter at all. Backends follow
    /// `WGPU_BACKEND` when it is set. `limits`: the device limits to request
    /// (`None`: everything the adapter supports); pass
    /// `wgpu::Limits::downlevel_webgl2_defaults()` to check a render fits WebGL2.
    pub async fn request(limits: Option<wgpu::Limits>) -> Result<Self, GpuError> {
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
        let mut adapter = None;
        let mut why = Vec::new();
        for fallback in [false, true] {
            let options = wgpu::RequestAdapterOptions {
                power_preference: wgpu::PowerPreference::HighPerformance,
                force_fallback_adapter: fallback,
                compatible_surface: None,
                ..Default::default()
            };
            match instance.request_adapter(&options).await {
                Ok(a) => {
                    adapter = Some(a);
                    break;
                }
                Err(e) => why.push(e.to_string()),
            }
        }
        if adapter.is_none() {
            adapter = instance
                .enumerate_adapters(wgpu::Backends::all())
                .await
                .into_iter()
                .next();
        }
        let adapter = adapter.ok_or_else(|| GpuError::NoAdapter(why.join("; ")))?;
        let required_limits = limits.unwrap_or_else(|| adapter.limits());
        let (device, queue) = adapter
            .request_device(&wgpu::DeviceDescriptor {
                label: Some("marbling-gpu"),
                required_limits,
                ..Default::default()
            })
            .await?;
        Ok(Self::from_parts(device, queue, adapter.get_info()))
    }

    /// [`GpuContext::request`] with all the adapter's limits, blocking (native only).
    #[cfg(not(target_arch = "wasm32"))]
    pub fn new_headless() -> Result<Self, GpuError> {
        pollster::block_on(Self::request(None))
    }

    /// [`GpuContext::request`] with the given limits, blocking (native only).
    #[cfg(not(target_arch = "wasm32"))]
    pub fn new_headless_with_limits(limits: wgpu::Limits) -> Result<Self, GpuError> {
        pollster::block_on(Self::request(Some(limits)))
    }

    /// "name (backend, device type)", for logs and benchmark reports.
    pub fn describe(&self) -> String {
        format!(
            "{} ({:?}, {:?})",
            self.info.name, self.info.backend, self.info.device_type
        )
    }

    /// The largest 2D texture side the device accepts.
    pub fn max_texture_side(&self) -> u32 {
        self.device.limits().max_texture_dimension_2d
    }

    /// Runs `f` and turns any wgpu validation or out-of-memory error it caused into a
    /// [`GpuError::Wgpu`] (instead of wgpu's default panic on uncaptured errors).
    pub fn checked<T>(&self, f: impl FnOnce() -> T) -> Result<T, GpuError> {
        let oom = self.device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let validation = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let out = f();
        let v = validation.pop();
        let o = oom.pop();
        let errors = block_on_ready(v).into_iter().chain(block_on_ready(o));
        match errors.map(|e| e.to_string()).reduce(|a, b| a + "; " + &b) {
            Some(msg) => Err(GpuError::Wgpu(msg)),
            None => Ok(out),
        }
    }
}

/// Waits for an error-scope future. wgpu-core resolves these immediately; on the web
/// (WebGPU) the browser resolves them later, where we do not block and report nothing.
fn block_on_ready<F: std::future::Future<Output = Option<wgpu::Error>>>(
    f: F,
) -> Option<wgpu::Error> {
    #[cfg(not(target_arch = "wasm32"))]
    {
        pollster::block_on(f)
    }
    #[cfg(target_arch = "wasm32")]
    {
        drop(f);
        None
    }
}
