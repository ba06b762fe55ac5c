//! Pictures, live video, MIDI, sound and the 3D view: backgrounds and input from outside
//! the program and the design seen on objects.

pub(crate) mod midi;
pub(crate) mod midi_input;
pub(crate) mod picture;
pub(crate) mod recorder;
pub(crate) mod sound;
pub(crate) mod sound_input;
pub(crate) mod step_clock;
pub(crate) mod video;
pub(crate) mod video_panel;
pub(crate) mod view3d;
pub(crate) mod view3d_displace;
pub(crate) mod view3d_panes;
pub(crate) mod view3d_recording;
pub(crate) mod view3d_style;
