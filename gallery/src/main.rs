//! Renders every example headless into `out/gallery/` and writes `index.html` showing each
//! picture beside the picture real Mesa/GLU renders from the C original (where there is one),
//! with the share of pixels that differ by the conformance tests' metric.
//!
//! `cargo run --release --example gallery`

use gleval::prelude::*;
use gleval::testing::compare::{compare, load_png, RgbImage};
use std::fmt::Write as _;
use std::path::Path;

#[path = "bcurve.rs"]
mod bcurve;
#[path = "bezcurve.rs"]
mod bezcurve;
#[path = "bezsurf.rs"]
mod bezsurf;
#[path = "bsurf.rs"]
mod bsurf;
#[path = "colormap.rs"]
mod colormap;
#[path = "demo.rs"]
mod demo;
#[path = "ex1_bezier.rs"]
mod ex1_bezier;
#[path = "ex2_bspline.rs"]
mod ex2_bspline;
#[path = "ex3_bspline_n.rs"]
mod ex3_bspline_n;
#[path = "ex4_bspline_surface.rs"]
mod ex4_bspline_surface;
#[path = "ex5_bird.rs"]
mod ex5_bird;
#[path = "flattwoviewports.rs"]
mod flattwoviewports;
#[path = "fogblend.rs"]
mod fogblend;
#[path = "labels.rs"]
mod labels;
#[path = "linespoints.rs"]
mod linespoints;
#[path = "lists.rs"]
mod lists;
#[path = "mipnurbs.rs"]
mod mipnurbs;
#[path = "operations.rs"]
mod operations;
#[path = "outline.rs"]
mod outline;
#[path = "rational.rs"]
mod rational;
#[path = "rationalmap.rs"]
mod rationalmap;
#[path = "shapes.rs"]
mod shapes;
#[path = "specular.rs"]
mod specular;
#[path = "stipple.rs"]
mod stipple;
#[path = "strokes.rs"]
mod strokes;
#[path = "teapot.rs"]
mod teapot;
#[path = "texgen.rs"]
mod texgen;
#[path = "texsurf.rs"]
mod texsurf;
#[path = "texteapot.rs"]
mod texteapot;
#[path = "trimmed.rs"]
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
    // Display, not Debug: a missing adapter's message says what to install.
    if let Err(e) = render_gallery() {
        eprintln!("gallery: {e}");
        std::process::exit(1);
    }
}

fn render_gallery() -> Result<(), Box<dyn std::error::Error>> {
    let out = Path::new("out/gallery");
    std::fs::create_dir_all(out)?;
    let references = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference/pictures/png");
    let mut html = String::from(
        "<!doctype html><meta charset=utf-8><title>gleval gallery</title>\
         <style>body{font-family:sans-serif}td{padding:6px;vertical-align:top}</style>\
         <h1>gleval gallery</h1><p>Left: gleval (wgpu). Right: real Mesa/GLU (OSMesa) from the C original.</p><table>",
    );
    println!("{:<12} {:>9}  title", "program", "differ");
    for (name, make) in PROGRAMS {
        let mut app = make();
        let title = app.title().to_owned();
        let image = app.render_image()?;
        let png = out.join(format!("{name}.png"));
        gleval::render::write_png(&png, &image)?;
        let reference = references.join(format!("{name}.png"));
        let score =
            load_png(&reference).ok().and_then(|r| compare(&r, &RgbImage::from_rgba(&image)).ok()).map(|c| c.fraction);
        let score_text = score.map_or("-".to_owned(), |s| format!("{:.3}%", s * 100.0));
        println!("{name:<12} {score_text:>9}  {title}");
        let reference_cell = if reference.exists() {
            std::fs::copy(&reference, out.join(format!("{name}.mesa.png")))?;
            format!("<img src=\"{name}.mesa.png\">")
        } else {
            "(no reference)".to_owned()
        };
        let _ = write!(
            html,
            "<tr><td><b>{name}</b><br>{title}<br>differs: {score_text}</td><td><img src=\"{name}.png\"></td><td>{reference_cell}</td></tr>"
        );
    }
    html.push_str("</table>");
    std::fs::write(out.join("index.html"), html)?;
    println!("wrote {}", out.join("index.html").display());
    Ok(())
}
