//! The one plotting style of the CLI's figures (study, simulate, batch, compare): the embedded
//! font (`assets/fonts/DejaVuSans.ttf`, registered once, never taken from the system), the
//! colours, the legend box and the atomic PNG writer. Drawing code only: no physics here.

use plotters::coord::{CoordTranslate, Shift};
use plotters::prelude::*;
use plotters::style::{FontStyle, register_font};
use pounding::output::write_atomic;
use std::path::Path;
use std::sync::Once;

static FONT: &[u8] = include_bytes!("../../../assets/fonts/DejaVuSans.ttf");
static REGISTER: Once = Once::new();

/// The font family every figure uses (the embedded DejaVu Sans).
pub const FAMILY: &str = "sans-serif";

/// Registers the embedded font under [`FAMILY`] (normal and bold); idempotent.
pub fn register() {
    REGISTER.call_once(|| {
        for style in [FontStyle::Normal, FontStyle::Bold] {
            // The bytes are a valid TrueType font shipped with the repository.
            let _ = register_font(FAMILY, style, FONT);
        }
    });
}

/// Result of a drawing step (the error is plotters' message).
pub type DrawResult<T = ()> = Result<T, String>;

/// Maps a plotters error to its message.
pub fn e<E: std::fmt::Display>(err: E) -> String {
    err.to_string()
}

/// Blue: lower bounds, first series.
pub const BLUE: RGBColor = RGBColor(31, 97, 180);
/// Red: upper bounds, second series.
pub const RED: RGBColor = RGBColor(200, 40, 40);
/// Green.
pub const GREEN: RGBColor = RGBColor(39, 150, 80);
/// Orange: outward slip.
pub const ORANGE: RGBColor = RGBColor(230, 126, 34);
/// Purple: inward slip.
pub const PURPLE: RGBColor = RGBColor(142, 68, 173);
/// Near-black.
pub const DARK: RGBColor = RGBColor(20, 20, 20);

/// Black text of `size` pixels in [`FAMILY`].
pub fn font(size: u32) -> TextStyle<'static> {
    (FAMILY, size).into_font().color(&BLACK)
}

/// The series legend: a translucent white box with a `border` at `position`, labels in
/// [`FAMILY`] at `size` pixels.
pub fn series_legend<'a, DB: DrawingBackend + 'a, CT: CoordTranslate>(
    chart: &mut ChartContext<'a, DB, CT>,
    position: SeriesLabelPosition,
    border: impl Into<ShapeStyle>,
    size: u32,
) -> DrawResult {
    chart
        .configure_series_labels()
        .position(position)
        .background_style(WHITE.mix(0.85))
        .border_style(border)
        .label_font((FAMILY, size))
        .draw()
        .map_err(e)
}

/// Draws a PNG of `size` pixels in memory with `draw` and writes it to `path` atomically
/// ([`write_atomic`]: a temporary beside it, renamed; removed on any error). Errors name `path`.
/// The bytes are those plotters' file backend writes (the same `image` PNG encoder, default
/// settings).
pub fn save_png<F>(path: &Path, (w, h): (u32, u32), draw: F) -> DrawResult
where
    F: FnOnce(&DrawingArea<BitMapBackend, Shift>) -> DrawResult,
{
    use image::ImageEncoder;
    let mut buf = vec![0u8; w as usize * h as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        draw(&root).map_err(|err| format!("cannot draw {}: {err}", path.display()))?;
        root.present()
            .map_err(|err| format!("cannot draw {}: {err}", path.display()))?;
    }
    let mut png = Vec::new();
    image::codecs::png::PngEncoder::new(&mut png)
        .write_image(&buf, w, h, image::ColorType::Rgb8)
        .map_err(|err| format!("cannot encode {}: {err}", path.display()))?;
    write_atomic(path, &png).map_err(|err| format!("cannot write {}: {err}", path.display()))
}

/// [`save_png`] of `dir/name` on a white background.
pub fn save_white_png(
    dir: &Path,
    name: &str,
    size: (u32, u32),
    draw: impl FnOnce(&DrawingArea<BitMapBackend, Shift>) -> DrawResult,
) -> DrawResult {
    save_png(&dir.join(name), size, |root| {
        root.fill(&WHITE).map_err(e)?;
        draw(root)
    })
}
