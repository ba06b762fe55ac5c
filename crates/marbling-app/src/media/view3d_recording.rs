//! *Record a turn* of the 3D view: the exact pane's antialiased frames, read back from
//! the GPU as they are drawn ([`PendingRead`]) and handed to the WebM recorder, until the
//! camera has turned once round.

use crate::media::recorder::Recorder;
use marbling_gpu::PendingRead;

/// The file a recorded turn downloads as.
pub const TURN_VIDEO: &str = "marbling-3d-turn.webm";

/// A turn being filmed.
pub struct TurnRecording {
    recorder: Recorder,
    /// Pane size the video has, pixels.
    pub size: [u32; 2],
    /// Degrees turned since it began (one whole turn ends it).
    pub turned: f64,
    /// Frames handed to the recorder.
    pub frames: u32,
    /// The last frame drawn, on its way back from the GPU.
    pub reading: Option<PendingRead>,
}

impl TurnRecording {
    /// Starts a recording of frames of `size` pixels.
    pub fn start(size: [u32; 2]) -> Result<Self, String> {
        Ok(Self {
            recorder: Recorder::start_frames(size[0], size[1])?,
            size,
            turned: 0.0,
            frames: 0,
            reading: None,
        })
    }

    /// Ends it: its video downloads (`whole`: after one whole turn) unless no frame came
    /// back in time. Returns the note saying which.
    pub fn finish(self, whole: bool) -> String {
        if self.frames == 0 {
            self.recorder.discard();
            return "the recording ended before a frame came back from the GPU: nothing to save"
                .to_owned();
        }
        self.recorder.finish(TURN_VIDEO);
        if whole {
            format!("recorded one turn: {TURN_VIDEO}")
        } else {
            format!("recording stopped after {:.0}°: {TURN_VIDEO}", self.turned)
        }
    }

    /// Hands the recorder the frame that came back from the GPU, if one did.
    pub fn feed(&mut self, device: &wgpu::Device) -> Result<(), String> {
        // Native backends deliver the map from `poll`; on the web it is a no-op.
        let _ = device.poll(wgpu::PollType::Poll);
        let Some(reading) = &self.reading else {
            return Ok(());
        };
        let [w, h] = self.size;
        let mut rgba = Vec::new();
        let Some(outcome) = reading.rows(|_, row| rgba.extend_from_slice(row)) else {
            return Ok(());
        };
        self.reading = None;
        outcome
            .map_err(|e| e.to_string())
            .and_then(|()| self.recorder.push_frame(w, h, &rgba))?;
        self.frames += 1;
        Ok(())
    }
}
