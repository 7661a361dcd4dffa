//! Times drawing a program's toolpath on a pixel layer, as the page does for
//! large paths: `cargo run --release --example render_time -- FILE [W H DPR
//! FRAMES [RGBA_OUT]]`, every frame a whole one; with `EDITED=FILE2`, each
//! frame after the first draws FILE2 and FILE alternately on the last
//! frame's pixels, as the page does after an edit (`Raster::kept`; all
//! that a frame keeps for the next one: `render::Kept`). With `ORBIT=1`,
//! each frame is a moving frame of the 3D view turned a degree further
//! (behaviour 10.8).
use std::time::Instant;

use offsetlab::render::{self, Font, Kept, Pen, Rect, Scene, Stroke, Surface};
use offsetlab::toolpath::Toolpath;

struct Layer {
    vector: bool,
    segments: usize,
    length: f64,
    at: (f64, f64),
    kept: Kept,
    size: (usize, usize),
    scale: f64,
    bytes: Vec<u8>,
}
impl Pen for Layer {
    fn begin_path(&mut self, _: &Stroke) {}
    fn move_to(&mut self, x: f64, y: f64) {
        self.at = (x, y);
    }
    fn line_to(&mut self, x: f64, y: f64) {
        self.segments += 1;
        self.length += (x - self.at.0).hypot(y - self.at.1);
        self.at = (x, y);
    }
    fn stroke(&mut self) {}
}
impl Surface for Layer {
    fn clear(&mut self, _: f64, _: f64, _: &str) {}
    fn kept(&mut self) -> Option<&mut Kept> {
        if self.vector {
            return None;
        }
        let (w, h, s) = (self.size.0, self.size.1, self.scale);
        self.kept.begin(w, h, (s, s)).then_some(&mut self.kept)
    }
    fn composite(&mut self, _: &offsetlab::render::Transform) {
        self.kept.raster().image(&mut self.bytes);
    }
    fn fill_rect(&mut self, _: Rect, _: &str, _: Option<&str>) {}
    fn fill_text(&mut self, _: &str, _: f64, _: f64, _: &Font) {}
    fn fill_polygon(&mut self, _: &[(f64, f64)], _: &str) {}
    fn circle(&mut self, _: f64, _: f64, _: f64, _: Option<&str>, _: Option<&Stroke>) {}
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let text = std::fs::read_to_string(&args[1]).expect("program");
    let num = |i: usize, d: f64| args.get(i).and_then(|a| a.parse().ok()).unwrap_or(d);
    let (w, h, dpr) = (num(2, 1000.0), num(3, 800.0), num(4, 2.0));
    let mut setup = offsetlab::Setup::default();
    setup.set_register("01=100").unwrap();
    let run = offsetlab::run(&text, &setup);
    let tp = Toolpath::from_run(&run);
    let mut layer = Layer {
        vector: std::env::var_os("VECTOR").is_some(),
        segments: 0,
        length: 0.0,
        at: (0.0, 0.0),
        kept: Kept::new(),
        size: ((w * dpr) as usize, (h * dpr) as usize),
        scale: dpr,
        bytes: Vec::new(),
    };
    let edited = std::env::var_os("EDITED").map(|f| {
        let text = std::fs::read_to_string(f).expect("edited program");
        Toolpath::from_run(&offsetlab::run(&text, &setup))
    });
    #[cfg(target_arch = "wasm32")]
    println!(
        "wasm memory before drawing {} MiB",
        core::arch::wasm32::memory_size(0) * 65536 / (1 << 20)
    );
    for frame in 0..num(5, 3.0) as usize {
        let drawn = match &edited {
            Some(other) if frame % 2 == 1 => other,
            Some(_) => &tp,
            None => {
                layer.kept.forget();
                &tp
            }
        };
        let t = Instant::now();
        if std::env::var_os("ORBIT").is_some() {
            let scene = Scene {
                plane: render::Plane::Orbit(render::Angles::ISO.turned(frame as f64, 0.0)),
                ..Scene::default()
            };
            render::draw_scene_moving(&mut layer, drawn, &scene, w, h);
        } else {
            render::draw_scene(&mut layer, drawn, &Scene::default(), w, h);
        }
        let kept = layer.kept.raster().kept();
        println!(
            "{} moves: {:.1} ms{}; {} vector segments, {:.0} CSS px long",
            drawn.len(),
            t.elapsed().as_secs_f64() * 1e3,
            if kept {
                " (on the last frame's pixels)"
            } else {
                ""
            },
            layer.segments,
            layer.length
        );
        layer.segments = 0;
        layer.length = 0.0;
        // Built for wasm (as the page's module): the memory it has grown to.
        #[cfg(target_arch = "wasm32")]
        println!(
            "  wasm memory {} MiB",
            core::arch::wasm32::memory_size(0) * 65536 / (1 << 20)
        );
    }
    if let Some(out) = args.get(6) {
        let raster = layer.kept.raster();
        let (w, h) = raster.size();
        let mut bytes = Vec::with_capacity(4 * w * h);
        for y in 0..h {
            for x in 0..w {
                bytes.extend_from_slice(&raster.pixel(x, y));
            }
        }
        std::fs::write(out, bytes).unwrap();
        println!("{w}x{h} RGBA written to {out}");
    }
}
