# Two commands do all set-up on a fresh machine (see README.md):
#   make run   — the main job
#   make test  — everything CI runs
# Targets install what they need when it is missing and are idempotent.

SHELL := /bin/bash
CARGO ?= cargo
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
MARBLING := target/release/marbling

.PHONY: run dist icons test test-long gallery audit setup-rust setup-gpu setup-web setup-browser fmt-check clippy unit wasm-check bench bench-numpy bench-gpu web browser-test noise-gallery bench-noise bench-noise-export bench-fastnoise2 bench-svg

# Must equal the wasm-bindgen version in Cargo.lock (see crates/marbling-app/Cargo.toml).
WASM_BINDGEN_VERSION := 0.2.130
CARGO_BIN := $(HOME)/.cargo/bin
export PATH := $(CARGO_BIN):$(PATH)

## Builds the web app and serves it on http://127.0.0.1:8080 (Ctrl+C stops it).
run: web
	node tools/build/serve.mjs dist 8080

## Rust toolchain pieces: the wasm32 target, rustfmt and clippy.
setup-rust:
	@rustup target list --installed | grep -qx wasm32-unknown-unknown || rustup target add wasm32-unknown-unknown
	@rustup component list --installed | grep -q '^rustfmt' || rustup component add rustfmt
	@rustup component list --installed | grep -q '^clippy' || rustup component add clippy

## Mesa lavapipe (software Vulkan) so GPU tests run without a GPU.
setup-gpu:
	@if ! ls /usr/share/vulkan/icd.d/lvp_icd*.json >/dev/null 2>&1 || ! ldconfig -p | grep -q libvulkan.so.1; then \
	  echo "installing mesa-vulkan-drivers (lavapipe)"; \
	  $(SUDO) apt-get update -qq && $(SUDO) DEBIAN_FRONTEND=noninteractive apt-get install -y -qq mesa-vulkan-drivers libvulkan1 >/dev/null; \
	fi

## wasm-bindgen-cli, compiled from crates.io when missing or of another version.
setup-web: setup-rust
	@wasm-bindgen --version 2>/dev/null | grep -q "$(WASM_BINDGEN_VERSION)" || cargo install wasm-bindgen-cli --version $(WASM_BINDGEN_VERSION)

## Debian's Chromium and the npm packages of the browser tests.
setup-browser:
	@command -v chromium >/dev/null || { $(SUDO) apt-get update -qq && $(SUDO) DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium >/dev/null; }
	@[ -d tests/browser/node_modules/playwright-core ] && [ -d tests/browser/node_modules/pngjs ] || (cd tests/browser && npm ci --no-audit --no-fund)

## The web app in dist/ (tools/build/build.mjs): the `web` profile (Cargo.toml,
## .cargo/config.toml), wasm-bindgen, index.html and web/, then tools/build/post_build.mjs
## (no name section, precompressed .br/.gz, the service worker's list). Prints the
## module's sizes.
web: setup-web
	node tools/build/build.mjs

## The static site in dist/ (relative paths: host the folder as it is, under any path).
dist: web
	@echo "dist/ is the static site: copy the folder to any web server"
	@ls -l dist/*.wasm dist/*.wasm.gz dist/*.wasm.br | awk '{print $$5, $$9}'

## Lighthouse on the served dist/ (headless Debian Chromium): performance, accessibility,
## best practices and the transfer size (see docs/BENCHMARKS.md).
audit: web setup-browser
	@[ -d tools/audit/node_modules/lighthouse ] || (cd tools/audit && npm ci --no-audit --no-fund)
	cd tools/audit && node audit.mjs

## The app's icons in web/, rendered from web/icon.json.
icons: $(MARBLING)
	$(MARBLING) render web/icon.json --width 512 -o web/icon-512.png
	$(MARBLING) render web/icon.json --width 192 -o web/icon-192.png
	$(MARBLING) render web/icon.json --width 180 -o web/apple-touch-icon.png
	$(MARBLING) render web/icon.json --width 32 -o web/favicon-32.png
	$(MARBLING) svg web/icon.json -o web/icon.svg

## End-to-end tests in headless Chromium on WebGPU and WebGL2 (SwiftShader): the short
## tier (tests/browser/harness.mjs, `longOnly`). The CLI that renders their references
## is target/debug/marbling as `cargo test --workspace` builds it (the test profile):
## after `unit` nothing is compiled again.
browser-test: web setup-browser
	$(CARGO) test --workspace --no-run
	cd tests/browser && MARBLING_BIN=$(CURDIR)/target/debug/marbling npm test

## Every browser test, the long tier too (second backends and screens, tile schedules,
## drag frames): about twice the short tier's time.
test-long: web setup-browser
	$(CARGO) test --workspace --no-run
	cd tests/browser && MARBLING_LONG=1 MONKEY_SEEDS=7,11 MARBLING_BIN=$(CURDIR)/target/debug/marbling npm test

fmt-check: setup-rust
	$(CARGO) fmt --all -- --check

clippy: setup-rust
	$(CARGO) clippy --workspace --all-targets -- -D warnings

unit: setup-rust setup-gpu
	WGPU_BACKEND=vulkan $(CARGO) test --workspace

wasm-check: setup-rust
	$(CARGO) clippy --target wasm32-unknown-unknown -p marbling-json -p marbling-core -p marbling-gpu -p marbling-noise -p marbling-vector -p marbling-app -- -D warnings

test: fmt-check clippy wasm-check unit browser-test

$(MARBLING): $(shell find crates -name '*.rs' -o -name Cargo.toml -o -name '*.wgsl') Cargo.toml
	$(CARGO) build --release -p marbling-cli

## Renders every traditional pattern to docs/gallery/patterns/NAME.png (the README's
## gallery), every example design to docs/gallery/NAME.png, and the app's prerendered
## gallery thumbnails, web/gallery-thumbnails.jpg.
gallery: $(MARBLING)
	$(CARGO) run -p marbling-app --example gallery_atlas
	@mkdir -p docs/gallery/patterns
	@for f in examples/patterns/*.json; do \
	  n=$$(basename $$f .json); $(MARBLING) render $$f -o docs/gallery/patterns/$$n.png --width 240 || exit 1; \
	done
	@for f in examples/designs/*.json; do \
	  n=$$(basename $$f .json); $(MARBLING) render $$f -o docs/gallery/$$n.png --width 320 || exit 1; \
	done

## Throughput of the CPU reference renderer (see docs/BENCHMARKS.md).
bench: $(MARBLING)
	$(MARBLING) bench --ops 10,100,1000,10000 --aa none --simd auto,off --repeat 3

## The same walk in numpy beside `marbling bench` (numpy and pillow from pip).
bench-numpy: $(MARBLING)
	python3 -m pip install --quiet numpy pillow
	python3 benches/numpy_walk.py --marbling $(MARBLING) --ops 1000

## GPU renderer: exact frames and live-editing frames (see docs/BENCHMARKS.md).
## The same commands run on lavapipe and on a real GPU.
bench-gpu: $(MARBLING) setup-gpu
	for s in 1024 1920x1080; do for aa in none rgss; do \
	  $(MARBLING) bench --backend gpu --mix mixed --ops 1000,10000 --size $$s --aa $$aa || exit 1; \
	done; done
	$(MARBLING) bench --backend gpu --pending --mix mixed --ops 1000,10000 --size 1920x1080 --aa rgss --frames 200

## Renders every example noise spec to docs/noise/NAME.png (256 px).
noise-gallery: $(MARBLING)
	@mkdir -p docs/noise
	@for f in examples/noise/*.json; do \
	  n=$$(basename $$f .json); $(MARBLING) noise $$f -o docs/noise/$$n.png --size 256 || exit 1; \
	done

## Noise throughput against fastnoise-lite, Gabor ms/megapixel (see docs/BENCHMARKS.md).
bench-noise: setup-gpu
	WGPU_BACKEND=vulkan $(CARGO) bench -p marbling-noise --bench noise

## Whole grids beside FastNoise2 v1.1.1 built from its public source (CMake from pip; a
## network or FASTNOISE2_SOURCE/FASTSIMD_SOURCE checkouts), one thread each.
bench-fastnoise2:
	benches/fastnoise2/run.sh

## Export time of a 4096² noise per type, CPU and GPU (see docs/BENCHMARKS.md).
bench-noise-export: setup-gpu
	WGPU_BACKEND=vulkan $(CARGO) bench -p marbling-noise --bench export

## Vector export at T = 1 on 1024² designs and the example designs: time, vertices, SVG
## size and agreement with the exact 4×4 render (see docs/BENCHMARKS.md).
bench-svg: $(MARBLING)
	$(MARBLING) bench-svg --size 1024 --aspect 1 --ops 100,300,1000 --tolerance 1 --mix mixed,drop-heavy,comb-heavy --check
	$(MARBLING) bench-svg --size 1024 --aspect 1 --ops 100,300 --tolerance 1 --mix all-types --check
	$(MARBLING) bench-svg examples/patterns/*.json examples/designs/*.json --scale 1.6 --tolerance 1 --check
