//! A small z-buffer rasteriser for the mesh view (`crashsim plot --what
//! mesh`): flat-coloured convex polygons in screen coordinates with a depth
//! per vertex, the nearest one winning each pixel, and the polygon's own
//! edges drawn over it when asked. Pure and deterministic: no GPU, no X.

/// An RGB image with a depth buffer; larger depth is nearer the viewer.
pub struct Canvas {
    pub width: usize,
    pub height: usize,
    pub rgb: Vec<[u8; 3]>,
    /// Depth of the nearest polygon at each pixel; −∞ where none covers it.
    depth: Vec<f64>,
}

/// A vertex on the screen: pixel x (right), pixel y (down), depth (nearer = larger).
pub type ScreenPoint = [f64; 3];

impl Canvas {
    pub fn new(width: usize, height: usize, background: [u8; 3]) -> Canvas {
        Canvas {
            width,
            height,
            rgb: vec![background; width * height],
            depth: vec![f64::NEG_INFINITY; width * height],
        }
    }

    /// Whether a polygon covers pixel `i` (row-major).
    pub fn is_covered(&self, i: usize) -> bool {
        self.depth[i] > f64::NEG_INFINITY
    }

    /// How many pixels polygons cover.
    pub fn covered_count(&self) -> usize {
        (0..self.depth.len())
            .filter(|&i| self.is_covered(i))
            .count()
    }

    /// Fills the convex polygon `p` with `fill`; pixels within `edge_px` of
    /// one of its sides take `edge` instead (when given).
    pub fn polygon(&mut self, p: &[ScreenPoint], fill: [u8; 3], edge: Option<([u8; 3], f64)>) {
        for k in 1..p.len().saturating_sub(1) {
            self.triangle([p[0], p[k], p[k + 1]], p, fill, edge);
        }
    }

    fn triangle(
        &mut self,
        t: [ScreenPoint; 3],
        outline: &[ScreenPoint],
        fill: [u8; 3],
        edge: Option<([u8; 3], f64)>,
    ) {
        let area = cross2(t[0], t[1], t[2]);
        if area.abs() < 1e-12 {
            return;
        }
        let (x0, x1) = pixel_span(t.map(|q| q[0]), self.width);
        let (y0, y1) = pixel_span(t.map(|q| q[1]), self.height);
        for y in y0..y1 {
            for x in x0..x1 {
                let c = [x as f64 + 0.5, y as f64 + 0.5, 0.0];
                // Barycentric weights, the same sign as the area inside.
                let w0 = cross2(t[1], t[2], c) / area;
                let w1 = cross2(t[2], t[0], c) / area;
                let w2 = 1.0 - w0 - w1;
                if w0 < -1e-9 || w1 < -1e-9 || w2 < -1e-9 {
                    continue;
                }
                let z = w0 * t[0][2] + w1 * t[1][2] + w2 * t[2][2];
                let i = y * self.width + x;
                if z <= self.depth[i] {
                    continue;
                }
                self.depth[i] = z;
                self.rgb[i] = match edge {
                    Some((colour, px)) if distance_to_outline(c, outline) < px => colour,
                    _ => fill,
                };
            }
        }
    }
}

/// The pixels [first, end) that the coordinates `v` span, within 0..n.
fn pixel_span(v: [f64; 3], n: usize) -> (usize, usize) {
    let lo = v
        .iter()
        .cloned()
        .fold(f64::INFINITY, f64::min)
        .floor()
        .max(0.0);
    let hi = v
        .iter()
        .cloned()
        .fold(f64::NEG_INFINITY, f64::max)
        .ceil()
        .max(0.0);
    ((lo as usize).min(n), (hi as usize).min(n))
}

/// Twice the signed area of the triangle a, b, c (x and y only).
fn cross2(a: ScreenPoint, b: ScreenPoint, c: ScreenPoint) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Distance in pixels from `c` to the nearest side of the closed polygon.
fn distance_to_outline(c: ScreenPoint, outline: &[ScreenPoint]) -> f64 {
    let n = outline.len();
    (0..n)
        .map(|k| {
            let (a, b) = (outline[k], outline[(k + 1) % n]);
            let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
            let len2 = dx * dx + dy * dy;
            let s = if len2 > 0.0 {
                (((c[0] - a[0]) * dx + (c[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let (px, py) = (a[0] + s * dx - c[0], a[1] + s * dy - c[1]);
            (px * px + py * py).sqrt()
        })
        .fold(f64::INFINITY, f64::min)
}

/// The rainbow scale of crash post-processors: blue (0), cyan, green,
/// yellow, red (1); `t` is clamped to [0, 1].
pub fn rainbow(t: f64) -> [u8; 3] {
    const STOPS: [[f64; 3]; 5] = [
        [0.0, 0.0, 255.0],
        [0.0, 255.0, 255.0],
        [0.0, 255.0, 0.0],
        [255.0, 255.0, 0.0],
        [255.0, 0.0, 0.0],
    ];
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let s = t * 4.0;
    let k = (s.floor() as usize).min(3);
    let f = s - k as f64;
    let (a, b) = (STOPS[k], STOPS[k + 1]);
    [0, 1, 2].map(|c| (a[c] + f * (b[c] - a[c])).round() as u8)
}

/// `colour` darkened by `shade` in [0, 1] (1 = unchanged).
pub fn shaded(colour: [u8; 3], shade: f64) -> [u8; 3] {
    colour.map(|c| (c as f64 * shade.clamp(0.0, 1.0)).round() as u8)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_nearer_of_two_overlapping_squares_wins() {
        let mut c = Canvas::new(20, 20, [255; 3]);
        let sq = |z: f64, o: f64| {
            vec![
                [o, o, z],
                [o + 10.0, o, z],
                [o + 10.0, o + 10.0, z],
                [o, o + 10.0, z],
            ]
        };
        c.polygon(&sq(1.0, 5.0), [255, 0, 0], None);
        c.polygon(&sq(0.0, 2.0), [0, 0, 255], None); // farther, drawn after
        assert_eq!(c.rgb[7 * 20 + 7], [255, 0, 0]);
        assert_eq!(c.rgb[3 * 20 + 3], [0, 0, 255]);
        assert_eq!(c.rgb[18 * 20 + 18], [255; 3]);
        // 10 x 10 pixels each, 7 x 7 of them shared: 151 covered.
        assert_eq!(c.covered_count(), 151);
    }

    #[test]
    fn edges_are_drawn_only_near_the_polygon_sides() {
        let mut c = Canvas::new(20, 20, [255; 3]);
        let sq = [
            [2.0, 2.0, 0.0],
            [18.0, 2.0, 0.0],
            [18.0, 18.0, 0.0],
            [2.0, 18.0, 0.0],
        ];
        c.polygon(&sq, [0, 255, 0], Some(([0, 0, 0], 0.75)));
        assert_eq!(c.rgb[2 * 20 + 10], [0, 0, 0]);
        assert_eq!(c.rgb[10 * 20 + 10], [0, 255, 0]);
        // The fan's diagonal (corner 0 to corner 2) is not a side.
        assert_eq!(c.rgb[12 * 20 + 12], [0, 255, 0]);
    }

    #[test]
    fn the_rainbow_runs_from_blue_to_red() {
        assert_eq!(rainbow(0.0), [0, 0, 255]);
        assert_eq!(rainbow(0.5), [0, 255, 0]);
        assert_eq!(rainbow(1.0), [255, 0, 0]);
        assert_eq!(rainbow(2.0), [255, 0, 0]);
        assert_eq!(rainbow(0.125), [0, 128, 255]);
    }
}
