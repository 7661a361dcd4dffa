//! The page's session helpers shared by tests/session.rs and
//! tests/session_drawing.rs.

use offsetlab::render;
use offsetlab::render::svg::SvgSurface;
use offsetlab::session::view::ViewChange;
use offsetlab::session::{Session, read_setup};
use serde_json::Value;

/// Seed 000: the G45–G48 square, register 01 = 6.
pub const SQUARE: &str = include_str!("../data/seed000_square.nc");

/// Its setup: register 01 = 6.
pub const SQUARE_SETUP: &str = r#"{"offsets":{"01":6.0}}"#;

/// Runs `program` with `setup` (JSON text; None: the default setup) and
/// returns the answer as JSON, as the page receives it.
pub fn run(s: &mut Session, program: &str, setup: Option<&str>) -> Value {
    let answer = s.run(program.into(), read_setup(setup.map(Some)), |_| ());
    serde_json::to_value(answer).unwrap()
}

pub fn square() -> Session {
    let mut s = Session::new();
    run(&mut s, SQUARE, Some(SQUARE_SETUP));
    s
}

pub fn block(s: &Session, index: u32) -> Value {
    serde_json::to_value(s.block(index)).unwrap()
}

/// Draws the frame asked for at `width` × `height` CSS pixels and `dpr`,
/// as the page's canvas would (here on an SVG surface), unless the canvas
/// already shows it; true when it was drawn.
pub fn draw(s: &mut Session, width: u32, height: u32, dpr: f64) -> bool {
    let ask = s.ask_frame(width, height, dpr);
    if s.frame_shown(&ask) {
        return false;
    }
    let (w, h) = (f64::from(ask.css.0), f64::from(ask.css.1));
    let frame = render::draw_scene(&mut SvgSurface::new(), s.toolpath(), s.scene(), w, h);
    s.frame_drawn(&ask, frame, false);
    true
}

/// A view change from its JSON text, as the page sends it.
pub fn view_change(text: &str) -> ViewChange {
    serde_json::from_str(text).unwrap()
}
