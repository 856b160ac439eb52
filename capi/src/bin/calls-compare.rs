//! `calls-compare EXPECTED_DIR ACTUAL_DIR [MIN_AGREEING]`: compares the scripted-call
//! interpreter's output (`tests/reference/calls/interp.c` linked against gleval) with the
//! committed outputs of real Mesa, case by case, with the tolerances of the Rust interpreter's
//! test (`tests/it/mesa_calls.rs`): numbers within 2·10⁻⁵ (relative above 1; 10⁻⁴ for the
//! order-30 and texgen cases), everything else exactly. Prints the agreeing cases per script
//! and each case that differs with its first difference; exits 1 if fewer than MIN_AGREEING
//! cases agree (default: all).

use std::path::Path;
use std::process::ExitCode;

/// Lines grouped by `case NAME` headers.
fn cases(text: &str) -> Vec<(String, Vec<&str>)> {
    let mut out: Vec<(String, Vec<&str>)> = Vec::new();
    for line in text.lines() {
        match line.strip_prefix("case ") {
            Some(name) => out.push((name.to_owned(), Vec::new())),
            None => match out.last_mut() {
                Some(case) => case.1.push(line),
                None => out.push((String::new(), vec![line])),
            },
        }
    }
    out
}

/// Why two lines differ, token by token.
fn mismatch(ours: &str, mesa: &str, tol: f64) -> Option<String> {
    let (a, b): (Vec<&str>, Vec<&str>) = (ours.split(' ').collect(), mesa.split(' ').collect());
    if a.len() != b.len() {
        return Some(format!("{} tokens vs {}", a.len(), b.len()));
    }
    for (x, y) in a.iter().zip(&b) {
        let same = match (x.parse::<f64>(), y.parse::<f64>()) {
            (Ok(p), Ok(q)) => (p.is_nan() && q.is_nan()) || (p - q).abs() <= tol * q.abs().max(1.0),
            _ => x == y,
        };
        if !same {
            return Some(format!("{x} vs {y}"));
        }
    }
    None
}

/// The first difference of a case, if any.
fn case_difference(name: &str, ours: &[&str], mesa: &[&str]) -> Option<String> {
    let tol = if name.contains("order30") || mesa.iter().any(|l| l.contains("texgen")) { 1e-4 } else { 2e-5 };
    for (i, m) in mesa.iter().enumerate() {
        let o = ours.get(i).copied().unwrap_or("(missing)");
        if let Some(why) = mismatch(o, m, tol) {
            return Some(format!("{why}\n    ours: {o}\n    mesa: {m}"));
        }
    }
    (ours.len() > mesa.len()).then(|| format!("{} extra lines", ours.len() - mesa.len()))
}

/// (agreeing, total) cases of one script, printing the differing ones.
fn compare_script(name: &str, expected: &str, actual: &str) -> (usize, usize) {
    let (mesa, ours) = (cases(expected), cases(actual));
    let mut agree = 0;
    for (i, (case, mesa_lines)) in mesa.iter().enumerate() {
        let ours_lines = ours.get(i).filter(|(c, _)| c == case).map_or(&[][..], |(_, l)| &l[..]);
        match case_difference(case, ours_lines, mesa_lines) {
            None => agree += 1,
            Some(why) => println!("  {name}/{case}: {why}"),
        }
    }
    println!("{name}: {agree} of {} cases agree with Mesa", mesa.len());
    (agree, mesa.len())
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (Some(expected_dir), Some(actual_dir)) = (args.first(), args.get(1)) else {
        eprintln!("usage: calls-compare EXPECTED_DIR ACTUAL_DIR [MIN_AGREEING]");
        return ExitCode::from(2);
    };
    let mut files: Vec<_> = match std::fs::read_dir(expected_dir) {
        Ok(dir) => {
            dir.filter_map(|e| e.ok().map(|e| e.path())).filter(|p| p.extension().is_some_and(|e| e == "out")).collect()
        }
        Err(e) => {
            eprintln!("calls-compare: {expected_dir}: {e}");
            return ExitCode::from(2);
        }
    };
    files.sort();
    let (mut agree, mut total) = (0, 0);
    for path in &files {
        let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let expected = std::fs::read_to_string(path).unwrap_or_default();
        let actual = std::fs::read_to_string(Path::new(actual_dir).join(&name)).unwrap_or_default();
        let (a, t) = compare_script(&name, &expected, &actual);
        (agree, total) = (agree + a, total + t);
    }
    println!("calls: {agree} of {total} cases agree with Mesa");
    let min = args.get(2).and_then(|m| m.parse().ok()).unwrap_or(total);
    if agree >= min {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}
