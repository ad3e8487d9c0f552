//! Text in the pictures `crashsim plot` draws: the font and how numbers are
//! written.
//!
//! Text is drawn with ab_glyph from a TrueType font read at run time
//! (`$CRASHSIM_FONT`, else DejaVu Sans from Debian's fonts-dejavu-core,
//! which ci/setup installs): no fontconfig or freetype at build time.

use plotters::style::FontStyle;

const FONT_PATHS: [&str; 3] = [
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/TTF/DejaVuSans.ttf",
    "/usr/share/fonts/dejavu/DejaVuSans.ttf",
];

/// Registers the font plotters draws text with (once).
pub fn register_font() -> Result<(), String> {
    static DONE: std::sync::OnceLock<Result<(), String>> = std::sync::OnceLock::new();
    DONE.get_or_init(|| {
        let candidates: Vec<String> = std::env::var("CRASHSIM_FONT")
            .ok()
            .into_iter()
            .chain(FONT_PATHS.iter().map(|s| s.to_string()))
            .collect();
        for p in &candidates {
            if let Ok(bytes) = std::fs::read(p) {
                let bytes: &'static [u8] = Box::leak(bytes.into_boxed_slice());
                return plotters::style::register_font("sans-serif", FontStyle::Normal, bytes)
                    .map_err(|_| format!("{p}: not a TrueType font: set CRASHSIM_FONT to a .ttf file"));
            }
        }
        Err(format!(
            "no TrueType font for the plot's text: install fonts-dejavu-core (looked for {}) or set CRASHSIM_FONT to a .ttf file",
            candidates.join(", ")
        ))
    })
    .clone()
}

/// A tick label: plain decimals for moderate magnitudes, else exponent form.
pub fn tick(v: &f64) -> String {
    let a = v.abs();
    if a == 0.0 || a < 1e-12 {
        "0".into()
    } else if (1e-3..1e5).contains(&a) {
        let digits = (3 - a.log10().floor() as i32).clamp(0, 6) as usize;
        let s = format!("{v:.digits$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        format!("{v:.2e}")
    }
}
