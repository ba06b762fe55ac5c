//! The WGSL twins of the CPU noises (`shaders/*.wgsl`, same function names and the same
//! u32 hash) and the helper that assembles a module from its dependencies (WGSL has no
//! includes); the uniform that `sample_noise` in `noise.wgsl` reads is
//! [`crate::noise_gpu`].

/// `hash.wgsl`: pcg_hash, lattice_hash, cell_hash, unit_f32, the cell stream, Poisson.
pub const HASH: &str = include_str!("../shaders/hash.wgsl");
/// `perlin.wgsl`: fade, perlin2, perlin2_periodic, perlin2_with_gradient.
pub const PERLIN: &str = include_str!("../shaders/perlin.wgsl");
/// `perlin3.wgsl`: perlin3, fbm3 (3D Perlin and its fBm).
pub const PERLIN3: &str = include_str!("../shaders/perlin3.wgsl");
/// `value.wgsl`: value2, value2_periodic.
pub const VALUE: &str = include_str!("../shaders/value.wgsl");
/// `fbm.wgsl`: FbmParams, fbm, fbm_with_gradient.
pub const FBM: &str = include_str!("../shaders/fbm.wgsl");
/// `worley.wgsl`: worley2, worley_normalised.
pub const WORLEY: &str = include_str!("../shaders/worley.wgsl");
/// `white.wgsl`: white2.
pub const WHITE: &str = include_str!("../shaders/white.wgsl");
/// `curl.wgsl`: curl_velocity, curl_component.
pub const CURL: &str = include_str!("../shaders/curl.wgsl");
/// `gabor.wgsl`: GaborParams, gabor, gabor_raw.
pub const GABOR: &str = include_str!("../shaders/gabor.wgsl");
/// `gabor_drive.wgsl`: gabor_drive, the driving fBms at an impulse.
pub const GABOR_DRIVE: &str = include_str!("../shaders/gabor_drive.wgsl");
/// `gabor_drive_off.wgsl`: the `gabor_drive` of modules without a
/// [`NoiseKind::DrivenGabor`] (no fBm compiled for it).
pub const GABOR_DRIVE_OFF: &str = include_str!("../shaders/gabor_drive_off.wgsl");
/// `fibers.wgsl`: FiberParams, fibers, fibers_height, fibers_specks.
pub const FIBERS: &str = include_str!("../shaders/fibers.wgsl");
/// `transfer.wgsl`: noise_to_grey, threshold_transfer, spline_decay, hsv_value_blend.
pub const TRANSFER: &str = include_str!("../shaders/transfer.wgsl");
/// `noise.wgsl`: NoiseUniform (the dispatcher `sample_noise` is
/// [`sample_noise_wgsl`]'s).
pub const NOISE: &str = include_str!("../shaders/noise.wgsl");
/// `layers.wgsl`: combine_layer, NoiseStack and stack_intensity.
pub const LAYERS: &str = include_str!("../shaders/layers.wgsl");

/// Every shader file by name, in dependency order.
pub const FILES: &[(&str, &str)] = &[
    ("hash", HASH),
    ("perlin", PERLIN),
    ("perlin3", PERLIN3),
    ("value", VALUE),
    ("fbm", FBM),
    ("worley", WORLEY),
    ("white", WHITE),
    ("curl", CURL),
    ("gabor", GABOR),
    ("gabor_drive", GABOR_DRIVE),
    ("fibers", FIBERS),
    ("transfer", TRANSFER),
    ("noise", NOISE),
    ("layers", LAYERS),
];

/// The files of the `layers` module, in order; the `noise` module's are these without
/// `layers`.
const LAYERS_FILES: &[&str] = &[
    "hash",
    "perlin",
    "value",
    "fbm",
    "worley",
    "white",
    "curl",
    "gabor",
    "gabor_drive",
    "fibers",
    "transfer",
    "noise",
    "layers",
];

/// The files a module needs, itself last.
#[must_use]
pub fn dependencies(name: &str) -> Option<&'static [&'static str]> {
    Some(match name {
        "hash" => &["hash"],
        "perlin" => &["hash", "perlin"],
        "perlin3" => &["hash", "perlin", "perlin3"],
        "value" => &["hash", "perlin", "value"],
        "fbm" => &["hash", "perlin", "value", "fbm"],
        "worley" => &["hash", "worley"],
        "white" => &["hash", "white"],
        "curl" => &["hash", "perlin", "value", "fbm", "curl"],
        "gabor" | "gabor_drive" => &["hash", "perlin", "value", "fbm", "gabor", "gabor_drive"],
        "fibers" => &["hash", "fibers"],
        "transfer" => &["transfer"],
        "noise" => &LAYERS_FILES[..LAYERS_FILES.len() - 1],
        "layers" => LAYERS_FILES,
        _ => return None,
    })
}

/// A noise type, as `NoiseGpu::noise_type` numbers it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u32)]
pub enum NoiseKind {
    /// Sparse Gabor noise.
    Gabor = 0,
    /// Perlin or value fBm.
    Fbm = 1,
    /// Worley noise.
    Worley = 2,
    /// White noise.
    White = 3,
    /// Curl noise.
    Curl = 4,
    /// Paper or canvas fibres.
    Fibers = 5,
    /// Sparse Gabor noise whose orientation or frequency an fBm drives: its own type so
    /// that a module for undriven Gabor noise compiles no fBm (on SwiftShader the drives
    /// were about half of a Gabor module's compile).
    DrivenGabor = 6,
}

impl NoiseKind {
    /// Every type, in `noise_type` order.
    pub const ALL: [NoiseKind; 7] = [
        NoiseKind::Gabor,
        NoiseKind::Fbm,
        NoiseKind::Worley,
        NoiseKind::White,
        NoiseKind::Curl,
        NoiseKind::Fibers,
        NoiseKind::DrivenGabor,
    ];

    /// The type of `noise_type` (`None` for none).
    pub fn of(noise_type: u32) -> Option<NoiseKind> {
        Self::ALL.get(noise_type as usize).copied()
    }

    /// Short name, for labels.
    pub fn name(self) -> &'static str {
        match self {
            NoiseKind::Gabor => "gabor",
            NoiseKind::Fbm => "fbm",
            NoiseKind::Worley => "worley",
            NoiseKind::White => "white",
            NoiseKind::Curl => "curl",
            NoiseKind::Fibers => "fibers",
            NoiseKind::DrivenGabor => "driven_gabor",
        }
    }

    /// `sample_noise`'s value for this type: WGSL of `p` and the uniform `u` (a WGSL
    /// expression of type `NoiseUniform`).
    fn call(self, u: &str) -> String {
        let call = match self {
            NoiseKind::Gabor | NoiseKind::DrivenGabor => {
                "gabor(p, {u}.gabor, {u}.gabor_orientation_drive, {u}.gabor_frequency_drive)"
            }
            NoiseKind::Fbm => "fbm(p, {u}.fbm)",
            NoiseKind::Worley => {
                "worley_normalised(p * {u}.frequency, {u}.seed, {u}.feature, {u}.metric, {u}.period)"
            }
            NoiseKind::White => "white2(p, {u}.seed, {u}.period)",
            NoiseKind::Curl => "curl_component(p, {u}.fbm, {u}.feature)",
            NoiseKind::Fibers => "fibers(p, {u}.fibers, {u}.fiber_grid, {u}.speck_grid)",
        };
        call.replace("{u}", u)
    }
}

/// Where `sample_noise` reads its [`crate::noise_gpu::NoiseGpu`] uniform.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UniformAt<'a> {
    /// Its argument: `sample_noise(p: vec2<f32>, u: NoiseUniform)`.
    Argument,
    /// Element `i` of a module-scope array, `sample_noise(p: vec2<f32>, i: u32)`
    /// reading `ARRAY[i]` (e.g. `surface.noises`): no 304-byte struct is copied, which
    /// on SwiftShader cut a Gabor module's compile by about a sixth.
    Element(&'a str),
}

/// A set of noise types: what a module's `sample_noise` can draw. A shader holding
/// only the types a design uses compiles and runs far faster on SwiftShader, which
/// compiles and runs every case of a switch (measured in the browser: a Perlin
/// background 40 s with a 10 s compile for every type, 9 s for Perlin's alone).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct NoiseKinds(u8);

impl NoiseKinds {
    /// No noise.
    pub const NONE: NoiseKinds = NoiseKinds(0);
    /// Every type.
    pub const ALL: NoiseKinds = NoiseKinds((1 << NoiseKind::ALL.len()) - 1);

    /// This set with `kind` in it.
    #[must_use]
    pub fn with(self, kind: NoiseKind) -> Self {
        NoiseKinds(self.0 | 1 << kind as u32)
    }

    /// True when `kind` is in the set.
    pub fn contains(self, kind: NoiseKind) -> bool {
        self.0 & 1 << kind as u32 != 0
    }

    /// True for the empty set.
    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// The types in the set, in `noise_type` order.
    pub fn iter(self) -> impl Iterator<Item = NoiseKind> {
        NoiseKind::ALL
            .into_iter()
            .filter(move |k| self.contains(*k))
    }

    /// The names of the types, joined by `+` (`all` for every type).
    pub fn name(self) -> String {
        if self == Self::ALL {
            return "all".to_owned();
        }
        self.iter()
            .map(NoiseKind::name)
            .collect::<Vec<_>>()
            .join("+")
    }
}

/// `sample_noise` drawing the types `kinds` (0 for any other `noise_type`), reading its
/// uniform `at`.
#[must_use]
pub fn sample_noise_wgsl(kinds: NoiseKinds, at: UniformAt) -> String {
    let (parameter, u) = match at {
        UniformAt::Argument => ("u: NoiseUniform".to_owned(), "u".to_owned()),
        UniformAt::Element(array) => ("i: u32".to_owned(), format!("{array}[i]")),
    };
    let cases: String = kinds
        .iter()
        .map(|k| {
            format!(
                "        case {}u: {{\n            return {};\n        }}\n",
                k as u32,
                k.call(&u)
            )
        })
        .collect();
    format!(
        "fn sample_noise(p: vec2<f32>, {parameter}) -> f32 {{\n    switch {u}.noise_type {{\n{cases}        default: {{\n            return 0.0;\n        }}\n    }}\n}}\n"
    )
}

/// The source of module `name` with its dependencies prepended, ready for
/// `create_shader_module` (append an entry point); `sample_noise` draws every type from
/// its argument.
#[must_use]
pub fn module(name: &str) -> Option<String> {
    module_for(name, NoiseKinds::ALL, UniformAt::Argument)
}

/// [`module`] with a `sample_noise` that draws only the types `kinds`, reading its
/// uniform `at`; without [`NoiseKind::DrivenGabor`] in `kinds` the Gabor noise has no
/// drives (`gabor_drive_off.wgsl`).
#[must_use]
pub fn module_for(name: &str, kinds: NoiseKinds, at: UniformAt) -> Option<String> {
    let deps = dependencies(name)?;
    let mut out = String::new();
    for d in deps {
        let (_, src) = FILES.iter().find(|(n, _)| n == d)?;
        let src = if *d == "gabor_drive" && !kinds.contains(NoiseKind::DrivenGabor) {
            GABOR_DRIVE_OFF
        } else {
            src
        };
        out.push_str(src);
        out.push('\n');
        if *d == "noise" {
            out.push_str(&sample_noise_wgsl(kinds, at));
        }
    }
    Some(out)
}
