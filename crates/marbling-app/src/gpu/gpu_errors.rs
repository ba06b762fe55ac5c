//! wgpu errors that no error scope caught (a shader the driver rejects, a pipeline that
//! could not be built). wgpu's default handler panics on them, which on the web kills the
//! page and the user's work with it; the app installs this collector instead, and shows
//! what it caught as an error message (`data-error`) while the design stays editable.

use std::sync::{Arc, Mutex};

/// Messages of uncaptured wgpu errors, oldest first, until the app takes them.
#[derive(Clone, Debug, Default)]
pub struct GpuErrors(Arc<Mutex<Vec<String>>>);

impl GpuErrors {
    /// Routes `device`'s uncaptured errors here (and asks `ctx` for a frame to show them).
    pub fn watch(&self, device: &wgpu::Device, ctx: &egui::Context) {
        let errors = self.clone();
        let ctx = ctx.clone();
        device.on_uncaptured_error(Arc::new(move |e: wgpu::Error| {
            log::error!("uncaptured GPU error: {e}");
            errors.push(&e.to_string());
            ctx.request_repaint();
        }));
    }

    /// Records one error as a one-line message.
    pub fn push(&self, error: &str) {
        let line = summary(error);
        if let Ok(mut list) = self.0.lock()
            && list.last() != Some(&line)
        {
            list.push(line);
        }
    }

    /// The errors caught since the last call.
    pub fn take(&self) -> Vec<String> {
        self.0
            .lock()
            .map(|mut list| std::mem::take(&mut *list))
            .unwrap_or_default()
    }
}

/// A one-line summary of a (often multi-line) wgpu error: its first non-empty line and
/// the driver's own message when there is one (e.g. ANGLE's shader compiler output).
pub fn summary(error: &str) -> String {
    let mut lines = error.lines().map(str::trim).filter(|l| !l.is_empty());
    let first = lines.next().unwrap_or("unknown error").to_owned();
    let detail = lines.find(|l| l.contains("ERROR") || l.contains("error:"));
    match detail {
        Some(d) if d != first => format!("GPU error: {first} ({d})"),
        _ => format!("GPU error: {first}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn summary_keeps_the_first_line_and_the_driver_error() {
        let e = "Validation Error\n\nCaused by:\n  In Device::create_render_pipeline\n    \
                 Internal error in ShaderStages(FRAGMENT) shader: \n\
                 ERROR: 0:12: 'SurfaceLayer' : Reference of struct type exceeds nesting\n";
        assert_eq!(
            summary(e),
            "GPU error: Validation Error (ERROR: 0:12: 'SurfaceLayer' : Reference of struct \
             type exceeds nesting)"
        );
        assert_eq!(summary(""), "GPU error: unknown error");
        assert_eq!(summary("Out of memory"), "GPU error: Out of memory");
    }

    #[test]
    fn repeated_errors_are_kept_once_and_taken_once() {
        let errors = GpuErrors::default();
        errors.push("a");
        errors.push("a");
        errors.push("b");
        assert_eq!(errors.take(), ["GPU error: a", "GPU error: b"]);
        assert!(errors.take().is_empty());
    }
}
