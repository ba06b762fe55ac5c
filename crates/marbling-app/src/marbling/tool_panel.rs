//! The side panel's Tool section: the tool buttons and the selected tool's parameters,
//! with the antialiasing choice.

use crate::frame::Frame;
use crate::marbling::drop_patterns::DropPattern;
use crate::marbling::tools::ToolKind;
use egui::{RichText, Slider};
use marbling_core::Antialias;

/// The Tool section: it sets the tool preferences ([`Frame::prefs`]).
pub(crate) fn ui(ui: &mut egui::Ui, frame: &mut Frame<'_>) {
    ui.label(RichText::new("Tool").strong());
    ui.horizontal_wrapped(|ui| {
        for (i, t) in ToolKind::ALL.into_iter().enumerate() {
            let mut button = ui.selectable_value(&mut frame.prefs.tool, t, t.label());
            if let Some(key) = crate::marbling::tools::TOOL_KEYS.get(i) {
                button = button.on_hover_text(format!("key {}", key.symbol_or_name()));
            }
            frame.control(format!("tool-{}", t.name()), &button);
        }
    });
    // The pen-pressure box's response, named after `s` is done with the prefs.
    let mut pressure_control = None;
    let s = &mut frame.prefs.settings;
    match frame.prefs.tool {
        ToolKind::Drop => {
            ui.label(if frame.layout.touch() {
                "Tap to drop; hold to grow."
            } else {
                "Click to drop; hold to grow."
            });
            ui.add(
                Slider::new(&mut s.drop_radius, crate::marbling::tools::DROP_RADIUS)
                    .text("radius")
                    .logarithmic(true),
            );
            ui.add(Slider::new(&mut s.drop_growth, 0.0..=400.0).text("growth /s"));
            ui.add(
                Slider::new(&mut s.drop_max_radius, 1.0..=2000.0)
                    .text("max radius")
                    .logarithmic(true),
            );
            ui.horizontal(|ui| {
                egui::ComboBox::from_id_salt("drop-pattern")
                    .selected_text(s.drop_pattern.label())
                    .show_ui(ui, |ui| {
                        for p in DropPattern::ALL {
                            ui.selectable_value(&mut s.drop_pattern, p, p.label());
                        }
                    })
                    .response
                    .on_hover_text("a pattern lays many drops at once; ghosts show where");
                ui.checkbox(&mut s.cycle_colors, "cycle colours")
                    .on_hover_text("each drop takes the next colour of the palette");
            });
            let pressure = ui
                .checkbox(&mut s.pressure, "pen pressure")
                .on_hover_text("a pen pressed harder (or a finger's force) makes the drop up to twice as large, a light touch down to a quarter");
            pressure_control = Some(pressure);
            match s.drop_pattern {
                DropPattern::Single => {}
                DropPattern::Line | DropPattern::Coil => {
                    ui.add(Slider::new(&mut s.pattern_count, 2..=400).text("drops"));
                    ui.add(
                        Slider::new(&mut s.pattern_spacing, 2.0..=400.0)
                            .text("spacing")
                            .logarithmic(true),
                    );
                }
                DropPattern::Ring => {
                    ui.add(Slider::new(&mut s.pattern_rings, 1..=20).text("rings"));
                    ui.add(
                        Slider::new(&mut s.pattern_spacing, 2.0..=400.0)
                            .text("spacing")
                            .logarithmic(true),
                    );
                }
                DropPattern::Grid => {
                    ui.add(Slider::new(&mut s.pattern_rows, 1..=40).text("rows"));
                    ui.add(Slider::new(&mut s.pattern_columns, 1..=40).text("columns"));
                    ui.add(
                        Slider::new(&mut s.pattern_spacing, 2.0..=400.0)
                            .text("spacing")
                            .logarithmic(true),
                    );
                    ui.add(Slider::new(&mut s.pattern_jitter, 0.0..=0.5).text("jitter"));
                    ui.checkbox(&mut s.pattern_serpentine, "serpentine order");
                }
                DropPattern::Scatter | DropPattern::Gaussian => {
                    ui.add(Slider::new(&mut s.pattern_count, 2..=1000).text("drops"));
                    ui.add(
                        Slider::new(&mut s.pattern_spread, 10.0..=4000.0)
                            .text("spread")
                            .logarithmic(true),
                    );
                }
            }
        }
        ToolKind::Stylus => {
            ui.label("Drag free-hand: the stylus pulls the ink along your path. Several tips make a free-hand comb.");
            ui.add(
                Slider::new(&mut s.stylus_wake, crate::marbling::tools::STYLUS_WAKE)
                    .text("wake")
                    .logarithmic(true),
            );
            ui.add(Slider::new(&mut s.stylus_tips, 1..=32).text("tips"));
            let pressure = ui
                .checkbox(&mut s.pressure, "pen pressure")
                .on_hover_text("a pen pressed harder widens the wake up to twice, a light touch narrows it to a quarter");
            pressure_control = Some(pressure);
            if s.stylus_tips > 1 {
                ui.add(
                    Slider::new(&mut s.stylus_spacing, 1.0..=400.0)
                        .text("tip spacing")
                        .logarithmic(true),
                );
            }
        }
        ToolKind::Jiggle => {
            ui.label("Drag sets the direction: the tank shakes along it.");
            ui.add(
                Slider::new(&mut s.jiggle_wavelength, 4.0..=2000.0)
                    .text("wavelength")
                    .logarithmic(true),
            );
            let limit = crate::marbling::tools::jiggle_along_limit(s.jiggle_wavelength);
            s.jiggle_along = s.jiggle_along.clamp(-limit, limit);
            ui.add(Slider::new(&mut s.jiggle_along, -limit..=limit).text("along"));
            ui.add(Slider::new(&mut s.jiggle_across, -200.0..=200.0).text("across"));
        }
        ToolKind::Shift => {
            ui.label("Drag: the whole tank moves with the pointer.");
        }
        ToolKind::Turn => {
            ui.label("Press at the centre, drag around it: the whole tank turns.");
        }
        ToolKind::Flow => {
            ui.label("Drag: the ink streams along a curl noise, about as far as you drag.");
            ui.horizontal(|ui| {
                ui.selectable_value(&mut s.flow_value, false, "Perlin");
                ui.selectable_value(&mut s.flow_value, true, "value");
                ui.label("noise");
            });
            ui.add(
                Slider::new(&mut s.flow_size, 20.0..=2000.0)
                    .text("noise size")
                    .logarithmic(true),
            );
            ui.add(Slider::new(&mut s.flow_octaves, 1..=4).text("octaves"));
            ui.add(
                Slider::new(&mut s.flow_strength, crate::marbling::tools::FLOW_STRENGTH)
                    .text("strength px")
                    .logarithmic(true),
            )
            .on_hover_text("how fast the ink streams, design px per unit of time");
            ui.add(Slider::new(&mut s.flow_seed, 0..=999).text("seed"));
        }
        ToolKind::Spray => {
            ui.label("Drag to spray droplets.");
            ui.add(
                Slider::new(&mut s.spray_density, 0.2..=20.0)
                    .text("density /10 px")
                    .logarithmic(true),
            );
            ui.add(
                Slider::new(&mut s.spray_min_radius, 0.2..=40.0)
                    .text("min size")
                    .logarithmic(true),
            );
            ui.add(
                Slider::new(&mut s.spray_max_radius, 0.2..=40.0)
                    .text("max size")
                    .logarithmic(true),
            );
            ui.add(
                Slider::new(&mut s.spray_spread, 1.0..=300.0)
                    .text("spread")
                    .logarithmic(true),
            );
        }
        ToolKind::Tine => {
            ui.label("Drag: the tine runs through the press point along the drag; longer drags pull harder.");
            ui.add(
                Slider::new(&mut s.tine_lambda, 0.5..=200.0)
                    .text("sharpness λ")
                    .logarithmic(true),
            );
        }
        ToolKind::Comb => {
            ui.label("Drag: parallel tines along the drag.");
            ui.add(Slider::new(&mut s.comb_tines, 0..=64).text("tines (0 = whole sheet)"));
            ui.add(
                Slider::new(&mut s.comb_spacing, crate::marbling::tools::COMB_SPACING)
                    .text("spacing")
                    .logarithmic(true),
            );
            ui.add(
                Slider::new(&mut s.comb_lambda, 0.5..=200.0)
                    .text("sharpness λ")
                    .logarithmic(true),
            );
        }
        ToolKind::Wavy => {
            ui.label("Drag sets the direction of the wave.");
            ui.add(Slider::new(&mut s.wavy_amplitude, -200.0..=200.0).text("amplitude"));
            ui.add(
                Slider::new(&mut s.wavy_wavelength, 4.0..=2000.0)
                    .text("wavelength")
                    .logarithmic(true),
            );
            ui.add(Slider::new(&mut s.wavy_phase, 0.0..=std::f64::consts::TAU).text("phase"));
        }
        ToolKind::Circular => {
            ui.label("Press at the centre, drag around it: the radius is your reach, the turn your strength.");
            ui.add(
                Slider::new(&mut s.circular_lambda, 0.5..=200.0)
                    .text("sharpness λ")
                    .logarithmic(true),
            );
        }
        ToolKind::Vortex => {
            ui.label("Press at the centre, drag around it to swirl.");
            ui.add(
                Slider::new(&mut s.vortex_lambda, 0.5..=400.0)
                    .text("sharpness λ")
                    .logarithmic(true),
            );
        }
    }
    if let Some(r) = pressure_control {
        frame.control("tool-pressure", &r);
    }
    egui::ComboBox::from_label("antialiasing")
        .selected_text(frame.prefs.antialias.name())
        .show_ui(ui, |ui| {
            for a in Antialias::ALL {
                ui.selectable_value(&mut frame.prefs.antialias, a, a.name());
            }
        });
}
