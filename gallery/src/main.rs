//! Renders every example headless into `out/gallery/` and writes `index.html` showing each
//! picture beside the picture real Mesa/GLU renders from the C original (where there is one),
//! with the share of pixels that differ by the conformance tests' metric, and what drew it.
//!
//! `cargo run --release -p gallery` (the CPU rasteriser), `cargo run --release -p gallery --
//! --wgpu` (wgpu; `GLEVAL_RASTERIZER=wgpu` does the same).
//!
//! The examples are gleval's (`examples/*.rs`), compiled here as modules: this package is not
//! an example of gleval so that building it builds none of gleval's dev-dependencies.

use gleval::prelude::*;
use gleval::render::Rasterizer;
use gleval::testing::compare::{compare, load_png, RgbImage};
use std::path::Path;

mod page;

#[path = "../../examples/bcurve.rs"]
mod bcurve;
#[path = "../../examples/bezcurve.rs"]
mod bezcurve;
#[path = "../../examples/bezsurf.rs"]
mod bezsurf;
#[path = "../../examples/bsurf.rs"]
mod bsurf;
#[path = "../../examples/colormap.rs"]
mod colormap;
#[path = "../../examples/demo.rs"]
mod demo;
#[path = "../../examples/ex1_bezier.rs"]
mod ex1_bezier;
#[path = "../../examples/ex2_bspline.rs"]
mod ex2_bspline;
#[path = "../../examples/ex3_bspline_n.rs"]
mod ex3_bspline_n;
#[path = "../../examples/ex4_bspline_surface.rs"]
mod ex4_bspline_surface;
#[path = "../../examples/ex5_bird.rs"]
mod ex5_bird;
#[path = "../../examples/flattwoviewports.rs"]
mod flattwoviewports;
#[path = "../../examples/fogblend.rs"]
mod fogblend;
#[path = "../../examples/labels.rs"]
mod labels;
#[path = "../../examples/linespoints.rs"]
mod linespoints;
#[path = "../../examples/lists.rs"]
mod lists;
#[path = "../../examples/mipnurbs.rs"]
mod mipnurbs;
#[path = "../../examples/operations.rs"]
mod operations;
#[path = "../../examples/outline.rs"]
mod outline;
#[path = "../../examples/rational.rs"]
mod rational;
#[path = "../../examples/rationalmap.rs"]
mod rationalmap;
#[path = "../../examples/shapes.rs"]
mod shapes;
#[path = "../../examples/specular.rs"]
mod specular;
#[path = "../../examples/stipple.rs"]
mod stipple;
#[path = "../../examples/strokes.rs"]
mod strokes;
#[path = "../../examples/teapot.rs"]
mod teapot;
#[path = "../../examples/texgen.rs"]
mod texgen;
#[path = "../../examples/texsurf.rs"]
mod texsurf;
#[path = "../../examples/texteapot.rs"]
mod texteapot;
#[path = "../../examples/trimmed.rs"]
mod trimmed;

/// A built-in program: its name and how to build it.
type Program = (&'static str, fn() -> App);

const PROGRAMS: [Program; 30] = [
    ("bezcurve", bezcurve::app),
    ("bezsurf", bezsurf::app),
    ("bcurve", bcurve::app),
    ("bsurf", bsurf::app),
    ("colormap", colormap::app),
    ("rationalmap", rationalmap::app),
    ("linespoints", linespoints::app),
    ("specular", specular::app),
    ("flattwoviewports", flattwoviewports::app),
    ("trimmed", trimmed::app),
    ("rational", rational::app),
    ("outline", outline::app),
    ("ex1bezier", ex1_bezier::app),
    ("ex2bspline", ex2_bspline::app),
    ("ex3bsplinen", ex3_bspline_n::app),
    ("ex4bsplinesurface", ex4_bspline_surface::app),
    ("ex5bird", ex5_bird::app),
    ("demo", demo::app),
    ("teapot", teapot::app),
    ("lists", lists::app),
    ("texsurf", texsurf::app),
    ("mipnurbs", mipnurbs::app),
    ("fogblend", fogblend::app),
    ("texteapot", texteapot::app),
    ("texgen", texgen::app),
    ("labels", labels::app),
    ("stipple", stipple::app),
    ("shapes", shapes::app),
    ("strokes", strokes::app),
    ("operations", operations::app),
];

fn main() {
    // Before wgpu starts (with --wgpu): no false "error" lines from Vulkan without a desktop.
    gleval::render::quiet_device_select();
    // Display, not Debug: a missing adapter's message says what to install.
    if let Err(e) = render_gallery() {
        eprintln!("gallery: {e}");
        std::process::exit(1);
    }
}

/// What drew a picture, for people: the page's and the terminal's words.
fn drawn_by(rasterizer: Rasterizer) -> &'static str {
    match rasterizer {
        Rasterizer::Cpu => "gleval's CPU rasteriser (gleval::render::soft)",
        Rasterizer::Wgpu => "wgpu (gleval::render::Renderer)",
    }
}

fn render_gallery() -> Result<(), Box<dyn std::error::Error>> {
    let wgpu = std::env::args().skip(1).any(|a| a == "--wgpu");
    let out = Path::new("out/gallery");
    std::fs::create_dir_all(out)?;
    let references = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/reference/pictures/png");
    println!("{:<12} {:>9}  title", "program", "differ");
    let mut rasterizers = Vec::new();
    let mut entries = Vec::new();
    for (name, make) in PROGRAMS {
        let mut app = make();
        if wgpu {
            app = app.with_rasterizer(Rasterizer::Wgpu);
        }
        let title = app.title().to_owned();
        let drawn_by = drawn_by(app.rasterizer());
        let image = app.render_image()?;
        let png = out.join(format!("{name}.png"));
        gleval::render::write_png(&png, &image)?;
        let reference = references.join(format!("{name}.png"));
        let score =
            load_png(&reference).ok().and_then(|r| compare(&r, &RgbImage::from_rgba(&image)).ok()).map(|c| c.fraction);
        let score_text = score.map_or("-".to_owned(), |s| format!("{:.3}%", s * 100.0));
        println!("{name:<12} {score_text:>9}  {title}");
        if !rasterizers.contains(&drawn_by) {
            rasterizers.push(drawn_by);
        }
        let has_reference = reference.exists();
        if has_reference {
            std::fs::copy(&reference, out.join(format!("{name}.mesa.png")))?;
        }
        entries.push(page::Entry { name, title, drawn_by, score: score_text, has_reference });
    }
    std::fs::write(out.join("index.html"), page::page(&entries))?;
    println!("drawn by {}; wrote {}", rasterizers.join(", "), out.join("index.html").display());
    Ok(())
}
