//! The gallery's page (`out/gallery/index.html`): one section a program, its two pictures side by
//! side and adjacent (gleval's, then real Mesa's), each as wide as it is or, when the pair is
//! wider than the window, both scaled down alike to fit it. A table would make every row as
//! wide as the widest picture (the operations sheet) and push the Mesa picture of a narrow row
//! off a window of ordinary size; a flex row per program does not.

use std::fmt::Write as _;

/// One program's entry.
pub struct Entry {
    /// The program's name: its pictures are `NAME.png` and `NAME.mesa.png`.
    pub name: &'static str,
    pub title: String,
    pub drawn_by: &'static str,
    /// The share of pixels that differ from Mesa's, as the page says it.
    pub score: String,
    /// Whether there is a Mesa picture.
    pub has_reference: bool,
}

const HEAD: &str = "<!doctype html><meta charset=utf-8>\
<meta name=viewport content=\"width=device-width, initial-scale=1\"><title>gleval gallery</title>\
<style>\
body{font-family:sans-serif;margin:1em}\
section{margin:0 0 1.5em}\
h2{font-size:110%;margin:0 0 .2em}\
p.about{margin:0 0 .4em;color:#333}\
.pair{display:flex;gap:8px;align-items:flex-start}\
figure{margin:0;flex:0 1 auto;min-width:0}\
figure img{display:block;max-width:100%;height:auto}\
figcaption{font-size:85%;color:#555}\
</style>\
<h1>gleval gallery</h1><p>Each program twice, side by side: gleval's picture, drawn headless by the \
rasteriser named above it, then real Mesa/GLU's (OSMesa, llvmpipe) from the C original.</p>";

/// The whole page.
pub fn page(entries: &[Entry]) -> String {
    let mut html = String::from(HEAD);
    for e in entries {
        let mesa = if e.has_reference {
            format!(
                "<figure><img src=\"{}.mesa.png\" alt=\"{} on Mesa\"><figcaption>real Mesa</figcaption></figure>",
                e.name, e.name
            )
        } else {
            "<figure><figcaption>(no Mesa picture)</figcaption></figure>".to_owned()
        };
        let _ = write!(
            html,
            "<section><h2>{name}</h2><p class=about>{title}. Drawn by {drawn_by}; differs from Mesa: {score}.</p>\
             <div class=pair><figure><img src=\"{name}.png\" alt=\"{name} on gleval\"><figcaption>gleval</figcaption>\
             </figure>{mesa}</div></section>",
            name = e.name,
            title = e.title,
            drawn_by = e.drawn_by,
            score = e.score,
        );
    }
    html
}

#[cfg(test)]
mod tests {
    //! The layout looked at in a browser: headless Chromium screenshots the page with pictures
    //! of one flat colour each, and the test finds where each colour landed.
    use super::*;
    use gleval::render::{write_png, Image};
    use gleval::testing::compare::{load_png, RgbImage};
    use std::path::Path;
    use std::process::Command;

    fn flat(width: u32, height: u32, rgb: [u8; 3]) -> Image {
        let pixels = (0..width * height).flat_map(|_| [rgb[0], rgb[1], rgb[2], 255]).collect();
        Image { width, height, pixels }
    }

    /// The box (x0, y0, x1, y1), ends excluded, of the pixels of colour `rgb`.
    fn bounds(shot: &RgbImage, rgb: [u8; 3]) -> Option<(u32, u32, u32, u32)> {
        let mut found: Option<(u32, u32, u32, u32)> = None;
        for y in 0..shot.height {
            for x in 0..shot.width {
                let k = 3 * (y * shot.width + x) as usize;
                if shot.rgb[k..k + 3] == rgb {
                    let b = found.get_or_insert((x, y, x + 1, y + 1));
                    *b = (b.0.min(x), b.1.min(y), b.2.max(x + 1), b.3.max(y + 1));
                }
            }
        }
        found
    }

    fn chromium() -> Option<&'static str> {
        ["chromium", "chromium-browser", "google-chrome"]
            .into_iter()
            .find(|c| Command::new(c).arg("--version").output().is_ok_and(|o| o.status.success()))
    }

    /// In a window 1400 pixels wide: a pair wider than the window (the operations sheet is
    /// 1200 pixels) is scaled down alike and both pictures are on screen; a narrow pair keeps
    /// its size and its two pictures stay next to each other.
    #[test]
    fn each_pair_is_side_by_side_and_fits_the_window() {
        let Some(browser) = chromium() else {
            if std::env::var_os("GLEVAL_NO_BROWSER").is_some() {
                eprintln!("no Chromium: the gallery's layout was not looked at (GLEVAL_NO_BROWSER)");
                return;
            }
            panic!("the gallery's layout check needs Chromium (apt-get install chromium), or GLEVAL_NO_BROWSER=1");
        };
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/gallery-layout");
        std::fs::create_dir_all(&dir).expect("a folder for the page");
        let (wide, wide_mesa, narrow, narrow_mesa) = ([255, 0, 0], [0, 0, 255], [0, 160, 0], [230, 200, 0]);
        write_png(dir.join("wide.png"), &flat(1200, 300, wide)).expect("png");
        write_png(dir.join("wide.mesa.png"), &flat(1200, 300, wide_mesa)).expect("png");
        write_png(dir.join("narrow.png"), &flat(300, 200, narrow)).expect("png");
        write_png(dir.join("narrow.mesa.png"), &flat(300, 200, narrow_mesa)).expect("png");
        let entry = |name| Entry {
            name,
            title: "a program".into(),
            drawn_by: "a rasteriser",
            score: "0%".into(),
            has_reference: true,
        };
        std::fs::write(dir.join("index.html"), page(&[entry("wide"), entry("narrow")])).expect("page");
        let shot = dir.join("shot.png");
        let _ = std::fs::remove_file(&shot);
        let status = Command::new(browser)
            .args(["--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--window-size=1400,1200"])
            .arg(format!("--screenshot={}", shot.display()))
            .arg(format!("file://{}", dir.join("index.html").canonicalize().expect("page").display()))
            .output()
            .expect("Chromium runs");
        assert!(shot.exists(), "no screenshot: {}", String::from_utf8_lossy(&status.stderr));
        let shot = load_png(&shot).expect("the screenshot");
        let [w, wm, n, nm] =
            [wide, wide_mesa, narrow, narrow_mesa].map(|c| bounds(&shot, c).expect("every picture on the page"));
        for (a, b, what) in [(w, wm, "the wide pair"), (n, nm, "the narrow pair")] {
            assert!(b.2 <= 1400, "{what}: Mesa's picture runs off the window ({b:?})");
            assert!(b.0 >= a.2 && b.0 - a.2 <= 16, "{what}: not side by side and adjacent ({a:?}, {b:?})");
            assert_eq!((a.2 - a.0, a.1, a.3), (b.2 - b.0, b.1, b.3), "{what}: scaled alike, on one row");
        }
        assert!(w.2 - w.0 < 700 && w.2 - w.0 > 600, "the wide pair shares the window ({w:?})");
        assert_eq!((n.2 - n.0, n.3 - n.1), (300, 200), "a narrow picture keeps its size");
        assert!(n.1 > w.3, "one program a row");
    }
}
