# Two commands do all set-up on a fresh machine (see README.md):
#   make run   — the main job
#   make test  — everything CI runs
# Targets install what they need when it is missing and are idempotent.

SHELL := /bin/bash
CARGO ?= cargo
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
MARBLING := target/release/marbling

.PHONY: run test gallery setup-rust setup-gpu fmt-check clippy unit wasm-check bench bench-svg

run: gallery

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

fmt-check: setup-rust
	$(CARGO) fmt --all -- --check

clippy: setup-rust
	$(CARGO) clippy --workspace --all-targets -- -D warnings

unit: setup-rust setup-gpu
	WGPU_BACKEND=vulkan $(CARGO) test --workspace

wasm-check: setup-rust
	$(CARGO) clippy --target wasm32-unknown-unknown -p marbling-core -p marbling-vector -- -D warnings

test: fmt-check clippy wasm-check unit

$(MARBLING): $(shell find crates -name '*.rs' -o -name Cargo.toml -o -name '*.wgsl') Cargo.toml
	$(CARGO) build --release -p marbling-cli

## Renders every example design to docs/gallery/NAME.png.
gallery: $(MARBLING)
	@mkdir -p docs/gallery
	@for f in examples/designs/*.json; do \
	  n=$$(basename $$f .json); $(MARBLING) render $$f -o docs/gallery/$$n.png --width 320 || exit 1; \
	done

## Throughput of the CPU reference renderer (see docs/BENCHMARKS.md).
bench: $(MARBLING)
	$(MARBLING) bench --ops 10,100,1000,10000 --aa none

## Vector export: time, vertices and SVG size (see docs/BENCHMARKS.md).
bench-svg: $(MARBLING)
	$(MARBLING) bench-svg --ops 50,200,1000 --tolerance 1,0.25 --raw
