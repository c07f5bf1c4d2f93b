//! Every SVG figure in `reports/` renders: it parses, draws its data (a real share of the
//! pixels are not background), and is not the one-line note `render_or_note` writes when a
//! figure could not be drawn (for example two series that look alike). `verify` writes the
//! same bytes as the committed files (CI compares them), so this checks what `verify` makes.

use resvg::{tiny_skia, usvg};

#[test]
fn every_report_figure_renders_with_content() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("reports");
    let mut names: Vec<_> = std::fs::read_dir(&dir)
        .expect("reports/ exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "svg"))
        .collect();
    names.sort();
    assert!(
        names.len() >= 25,
        "only {} figures in reports/",
        names.len()
    );
    for path in names {
        let name = path.display().to_string();
        let text = std::fs::read_to_string(&path).expect("readable");
        assert!(!text.contains("drawing figure failed"), "{name}: {text}");
        let tree = usvg::Tree::from_str(&text, &usvg::Options::default())
            .unwrap_or_else(|e| panic!("{name} does not parse: {e}"));
        let size = tree.size().to_int_size();
        assert!(
            size.width() >= 300 && size.height() >= 200,
            "{name}: {size:?}"
        );
        let mut pixmap = tiny_skia::Pixmap::new(size.width(), size.height()).expect("pixmap");
        resvg::render(&tree, tiny_skia::Transform::default(), &mut pixmap.as_mut());
        let drawn = pixmap
            .pixels()
            .iter()
            .filter(|p| p.alpha() > 0 && (p.red() < 200 || p.green() < 200 || p.blue() < 200))
            .count();
        let share = drawn as f64 / (size.width() * size.height()) as f64;
        assert!(
            share > 0.01,
            "{name}: only {:.2}% of the pixels are drawn",
            100.0 * share
        );
    }
}
