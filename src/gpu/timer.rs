//! The GPU's own time for compute passes, from timestamp queries (wgpu's
//! `Features::TIMESTAMP_QUERY`), on adapters that have them: what a benchmark needs to tell the
//! compute work from the submission, the wait and the driver around it, which wall time mixes
//! in (`examples/gpu_bench.rs`).

use super::device::{read_back, RenderError};

/// Timestamps at the beginning and end of up to `passes` compute passes.
pub struct PassTimer {
    queries: wgpu::QuerySet,
    resolved: wgpu::Buffer,
    passes: u32,
    /// Nanoseconds per timestamp tick.
    period: f32,
}

impl PassTimer {
    /// A timer for `passes` passes (at most 2048), or `None` when the device was made without
    /// timestamp queries (the adapter lacks them).
    #[must_use]
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue, passes: u32) -> Option<Self> {
        if !device.features().contains(wgpu::Features::TIMESTAMP_QUERY) || passes == 0 || passes > 2048 {
            return None;
        }
        let queries = device.create_query_set(&wgpu::QuerySetDescriptor {
            label: Some("pass timer"),
            ty: wgpu::QueryType::Timestamp,
            count: 2 * passes,
        });
        let resolved = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("pass timer resolved"),
            size: u64::from(2 * passes) * 8,
            usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        Some(Self { queries, resolved, passes, period: queue.get_timestamp_period() })
    }

    /// The timestamp writes of pass `index` (below the timer's `passes`).
    #[must_use]
    pub fn writes(&self, index: u32) -> wgpu::ComputePassTimestampWrites<'_> {
        let index = index.min(self.passes - 1);
        wgpu::ComputePassTimestampWrites {
            query_set: &self.queries,
            beginning_of_pass_write_index: Some(2 * index),
            end_of_pass_write_index: Some(2 * index + 1),
        }
    }

    /// Submits `encoder` (which recorded `used` timed passes), waits, and returns the sum of
    /// those passes' GPU time in seconds.
    pub fn read(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: wgpu::CommandEncoder,
        used: u32,
    ) -> Result<f64, RenderError> {
        let used = used.min(self.passes);
        let size = u64::from(2 * used.max(1)) * 8;
        let bytes = read_back(device, queue, encoder, size, |encoder, staging| {
            if used > 0 {
                encoder.resolve_query_set(&self.queries, 0..2 * used, &self.resolved, 0);
                encoder.copy_buffer_to_buffer(&self.resolved, 0, staging, 0, size);
            }
        })?;
        let ticks: Vec<u64> =
            bytes.chunks_exact(8).map(|b| u64::from_le_bytes(b.try_into().unwrap_or([0; 8]))).collect();
        let total: u64 = ticks.chunks_exact(2).take(used as usize).map(|p| p[1].saturating_sub(p[0])).sum();
        Ok(total as f64 * f64::from(self.period) * 1e-9)
    }
}
