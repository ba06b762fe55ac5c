//! Splitting an output into tiles no larger than a device's textures (used by headless
//! renders and by the app's exports).

/// Tiles (x0, y0, w, h) of at most `side` × `side` covering `width × height`, row-major.
pub fn tile_grid(width: u32, height: u32, side: u32) -> Vec<(u32, u32, u32, u32)> {
    let side = side.max(1);
    let mut tiles = Vec::new();
    for y0 in (0..height).step_by(side as usize) {
        for x0 in (0..width).step_by(side as usize) {
            tiles.push((x0, y0, side.min(width - x0), side.min(height - y0)));
        }
    }
    tiles
}

#[cfg(test)]
mod tests {
    use super::tile_grid;

    #[test]
    fn tiles_cover_the_output_once() {
        let tiles = tile_grid(10, 7, 4);
        assert_eq!(tiles.len(), 6);
        let area: u32 = tiles.iter().map(|t| t.2 * t.3).sum();
        assert_eq!(area, 70);
        assert_eq!(tiles[5], (8, 4, 2, 3));
    }
}
