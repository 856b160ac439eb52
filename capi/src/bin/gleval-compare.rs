//! `gleval-compare REFERENCE.png ACTUAL.png [THRESHOLD]`: the project's image metric
//! (`gleval::testing::compare`, tolerant of a one-pixel shift) between two PNGs, for the C
//! programs' pictures (`capi/tests/pictures.sh`). Prints the share of pixels that differ; with
//! a threshold (a fraction, 0.01 = 1%), exits 1 above it and writes `ACTUAL.diff.png`.

use gleval::testing::compare::{compare, diff_image, load_png, save_png};
use std::path::Path;
use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (Some(reference), Some(actual)) = (args.first(), args.get(1)) else {
        eprintln!("usage: gleval-compare REFERENCE.png ACTUAL.png [THRESHOLD]");
        return ExitCode::from(2);
    };
    let threshold = args.get(2).and_then(|t| t.parse::<f64>().ok());
    match run(Path::new(reference), Path::new(actual), threshold) {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(e) => {
            eprintln!("gleval-compare: {e}");
            ExitCode::from(2)
        }
    }
}

/// Compares and reports; false when the share is above the threshold.
fn run(reference: &Path, actual: &Path, threshold: Option<f64>) -> Result<bool, String> {
    let (r, a) = (load_png(reference)?, load_png(actual)?);
    let c = compare(&r, &a)?;
    println!("{:.3}% of pixels differ ({} of {})", c.fraction * 100.0, c.mismatched, r.width * r.height);
    let ok = threshold.is_none_or(|t| c.fraction <= t);
    if !ok {
        save_png(&actual.with_extension("diff.png"), &diff_image(&r, &c))?;
    }
    Ok(ok)
}
