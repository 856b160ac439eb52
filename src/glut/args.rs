//! `glutInit`'s arguments (GLUT 3 spec §2.1; freeglut's `fgParseCommandLineOptions`): gleval's
//! own options (`--png PATH`, `--time N`, `--frames N`, `--gpu`, `--wgpu`, `--profile`; what
//! [`Options`](crate::app::Options) holds) and GLUT's X options (`-display`, `-geometry`,
//! `-iconic`, `-direct`, `-indirect`, `-sync`, `-gldebug`) taken out of the program's, as
//! GLUT takes its own. The C ABI's `glutInit` and [`App::run`](crate::app::App::run) both read
//! them here.

/// gleval's options and whether each takes a value.
const GLEVAL_OPTIONS: [(&str, bool); 6] =
    [("--png", true), ("--time", true), ("--frames", true), ("--gpu", false), ("--wgpu", false), ("--profile", false)];

/// GLUT's X options and whether each takes a value.
const X_OPTIONS: [(&str, bool); 7] = [
    ("-display", true),
    ("-geometry", true),
    ("-iconic", false),
    ("-direct", false),
    ("-indirect", false),
    ("-sync", false),
    ("-gldebug", false),
];

/// GLUT's X options as `glutInit` found them.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct XOptions {
    /// `-display NAME`: the X display the windows open on.
    pub display: Option<String>,
    /// `-geometry WxH`: the initial window size.
    pub size: Option<(i32, i32)>,
    /// `-geometry +X+Y`: the initial window position.
    pub position: Option<(i32, i32)>,
    /// `-iconic`: windows open iconified.
    pub iconic: bool,
    /// `-direct` (true) or `-indirect` (false), the last given: `GLUT_DIRECT_RENDERING`.
    pub direct: Option<bool>,
    /// `-gldebug`: GL errors are reported after each display callback.
    pub gl_debug: bool,
}

impl XOptions {
    /// Reads the X options out of `args` (as [`split_init_args`] finds them).
    fn read(args: &[String]) -> Self {
        let mut x = Self::default();
        let mut i = 0;
        while i < args.len() {
            let value = args.get(i + 1).cloned().unwrap_or_default();
            match args[i].as_str() {
                "-geometry" => {
                    let (size, place) = parse_geometry(&value);
                    x.size = size.or(x.size);
                    x.position = place.or(x.position);
                    i += 1;
                }
                "-display" => {
                    x.display = Some(value);
                    i += 1;
                }
                "-iconic" => x.iconic = true,
                "-direct" => x.direct = Some(true),
                "-indirect" => x.direct = Some(false),
                "-gldebug" => x.gl_debug = true,
                // X's synchronous mode changes nothing a program can see.
                _ => {}
            }
            i += 1;
        }
        x
    }
}

impl XOptions {
    /// Whether an option sets a GLUT setting ([`Gl::glut_take_x_settings`](crate::gl::Gl::glut_take_x_settings)).
    #[must_use]
    pub fn sets_settings(&self) -> bool {
        self.iconic || self.direct.is_some()
    }
}

impl crate::gl::Gl {
    /// The X options that are GLUT settings `glutGet` reads back, as freeglut's `glutInit`
    /// takes them: `-iconic`, and `-direct`/`-indirect` as `GLUT_DIRECT_RENDERING`.
    pub fn glut_take_x_settings(&mut self, x: &XOptions) {
        use super::consts::*;
        if x.iconic {
            self.glut_init_iconic();
        }
        if let Some(direct) = x.direct {
            let mode = if direct { GLUT_FORCE_DIRECT_CONTEXT } else { GLUT_FORCE_INDIRECT_CONTEXT };
            self.glut_set_option(GLUT_DIRECT_RENDERING, mode);
        }
    }
}

/// `glutInit`'s split of a program's arguments (the first, the program's name, stays).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InitArgs {
    /// gleval's options with their values, in order (for `Options::from_args`).
    pub gleval: Vec<String>,
    /// GLUT's X options.
    pub x: XOptions,
    /// For each argument, whether it is the program's own (kept in `argv`).
    pub kept: Vec<bool>,
}

/// How many of `args` (from the first) are one option of `table` with its value; 0 if the
/// first is not one. `--png=PATH` is one argument.
fn option_len(args: &[String], table: &[(&str, bool)]) -> usize {
    let Some(first) = args.first() else { return 0 };
    if first.starts_with("--png=") && table == GLEVAL_OPTIONS {
        return 1;
    }
    match table.iter().find(|(name, _)| first == name) {
        Some((_, true)) => args.len().min(2),
        Some((_, false)) => 1,
        None => 0,
    }
}

/// Splits `args` (a program's `argv`, its name first) into gleval's options, GLUT's X options
/// and the program's own.
#[must_use]
pub fn split_init_args(args: &[String]) -> InitArgs {
    let (mut gleval, mut x) = (Vec::new(), Vec::new());
    let mut kept = vec![true; args.len()];
    let mut i = 1.min(args.len());
    while i < args.len() {
        let (n, into) = match option_len(&args[i..], &GLEVAL_OPTIONS) {
            0 => (option_len(&args[i..], &X_OPTIONS), &mut x),
            n => (n, &mut gleval),
        };
        if n == 0 {
            i += 1;
            continue;
        }
        into.extend_from_slice(&args[i..i + n]);
        kept[i..i + n].fill(false);
        i += n;
    }
    InitArgs { gleval, x: XOptions::read(&x), kept }
}

/// A size or a place: two numbers.
type Pair = Option<(i32, i32)>;

/// `-geometry WxH+X+Y` (each part optional, as X's geometry strings): size and place.
fn parse_geometry(g: &str) -> (Pair, Pair) {
    let (size, place) = match g.find(['+', '-']) {
        Some(at) => g.split_at(at),
        None => (g, ""),
    };
    let size = size.split_once(['x', 'X']).and_then(|(w, h)| Some((w.parse().ok()?, h.parse().ok()?)));
    let mut numbers = Vec::new();
    let mut rest = place;
    while let Some(sign) = rest.chars().next() {
        let body = &rest[1..];
        let end = body.find(['+', '-']).unwrap_or(body.len());
        let Ok(n) = body[..end].parse::<i32>() else { break };
        numbers.push(if sign == '-' { -n } else { n });
        rest = &body[end..];
    }
    let place = (numbers.len() == 2).then(|| (numbers[0], numbers[1]));
    (size, place)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn strings(args: &[&str]) -> Vec<String> {
        args.iter().map(|s| s.to_string()).collect()
    }

    #[test]
    fn options_leave_the_programs_arguments() {
        let args = strings(&[
            "prog",
            "-v",
            "--png",
            "a.png",
            "--gpu",
            "x",
            "--png=b.png",
            "-iconic",
            "-geometry",
            "40x30+5-6",
            "--frames",
        ]);
        let split = split_init_args(&args);
        assert_eq!(split.gleval, ["--png", "a.png", "--gpu", "--png=b.png", "--frames"]);
        let x = XOptions { size: Some((40, 30)), position: Some((5, -6)), iconic: true, ..XOptions::default() };
        assert_eq!(split.x, x);
        assert_eq!(split.kept, [true, true, false, false, false, true, false, false, false, false, false]);
    }

    #[test]
    fn x_options_as_freeglut_reads_them() {
        let args = strings(&["p", "-direct", "-display", ":7", "-indirect", "-sync", "-gldebug", "-geometry"]);
        let split = split_init_args(&args);
        let x = XOptions { display: Some(":7".into()), direct: Some(false), gl_debug: true, ..XOptions::default() };
        assert_eq!(split.x, x);
        assert_eq!(split.kept, [true, false, false, false, false, false, false, false]);
        assert_eq!(split_init_args(&[]).kept, Vec::<bool>::new());
    }

    #[test]
    fn geometry_strings() {
        assert_eq!(parse_geometry("40x30+5-6"), (Some((40, 30)), Some((5, -6))));
        assert_eq!(parse_geometry("640x480"), (Some((640, 480)), None));
        assert_eq!(parse_geometry("+10+20"), (None, Some((10, 20))));
        assert_eq!(parse_geometry("axb+1"), (None, None));
    }
}
