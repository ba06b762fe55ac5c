//! Setting a deep view on a prepared design: the per-tile reference records uploaded
//! and the deep variant of the pipeline chosen (`shaders/deep.wgsl`).

use super::textures::{op_texture, write_rows};
use super::{ExactRenderer, PreparedDesign, View};
use crate::GpuError;
use crate::deep::{DeepView, deep_records};

impl ExactRenderer {
    /// Draws the next frames of `prepared` as `view` by the deep walk: one f64
    /// reference per tile, each sample walking its offset from it in f32, so edges stay
    /// sharp at any zoom the f64 walk holds (10⁶× and beyond). A looping turbulence is
    /// drawn shallow (its two layers are not walked deep). [`PreparedDesign::set_view`]
    /// goes back to the plain walk.
    pub fn set_deep_view(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        prepared: &mut PreparedDesign,
        view: &DeepView,
    ) -> Result<(), GpuError> {
        let shallow = View {
            scale: view.scale,
            offset: [view.origin.x * view.scale, view.origin.y * view.scale],
            antialias: view.antialias,
        };
        if prepared.turbulence.is_some() {
            prepared.set_view(queue, &shallow);
            return Ok(());
        }
        let max_side = device.limits().max_texture_dimension_2d;
        let records = deep_records(&prepared.uploaded, prepared.records.len(), view, max_side)
            .ok_or(GpuError::TooManyOps {
                ops: prepared.records.len(),
                max_side,
            })?;
        let size = prepared.deep_texture.size();
        if (size.width, size.height) != (records.layout.width, records.layout.height) {
            prepared.deep_texture = op_texture(device, records.layout);
            self.rebind(device, prepared);
        }
        write_rows(
            queue,
            &prepared.deep_texture,
            records.layout,
            &records.records,
            0..records.records.len(),
        );
        prepared.view = View {
            offset: [0.0; 2],
            ..shallow
        };
        prepared.deep = Some([
            records.side,
            records.tiles_per_row,
            records.layout.ops_per_row.trailing_zeros(),
            records.per_tile,
        ]);
        self.variant_pipeline(device, prepared.variant());
        prepared.write_params(queue);
        Ok(())
    }
}
