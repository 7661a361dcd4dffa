//! The 3D view in the page's session (behaviour 10.8, 10.9): a drag turns
//! the mill's view from a plane into the 3D view, the view state and the
//! document carry its angles, and a link carries them in its `angles`
//! field; the lathe's ZX view turns into the lathe's 3D view (10.18),
//! its face view XC does not.

use offsetlab::render::svg::SvgSurface;
use offsetlab::session::view::ViewChange;
use offsetlab::session::{Session, read_setup};
use offsetlab::{render, share};

/// Seed 000: the G45–G48 square, register 01 = 6.
const SQUARE: &str = include_str!("data/seed000_square.nc");

fn session(program: &str, setup: &str) -> Session {
    let mut s = Session::new();
    s.run(program.into(), read_setup(Some(Some(setup))), |_| ());
    s
}

fn square() -> Session {
    session(SQUARE, r#"{"offsets":{"01":6.0}}"#)
}

fn change(json: &str) -> ViewChange {
    serde_json::from_str(json).unwrap()
}

/// Behaviour 10.8: a drag of (dx, dy) pixels turns the view by −dx/2 degrees
/// of yaw and dy/2 of pitch, from the plane's own angles. From the top view
/// (XY: yaw 0, pitch 90) a drag of (20, −40) gives yaw 0 − 10 = −10 → 350,
/// pitch 90 − 20 = 70.
#[test]
fn behaviour10_8_a_drag_turns_a_plane_view_into_the_3d_view() {
    let mut s = square();
    assert_eq!(s.view().angles, None, "a plane view reports no angles");
    assert!(s.orbit_by(20.0, -40.0));
    let v = s.view();
    assert_eq!(v.plane.as_deref(), Some("3D"));
    assert_eq!(v.angles, Some([350.0, 70.0]));
    // Again by (−40, 100): yaw 350 + 20 = 370 → 10; pitch 70 + 50 = 120
    // stops at 90.
    assert!(s.orbit_by(-40.0, 100.0));
    assert_eq!(s.view().angles, Some([10.0, 90.0]));
    // From the front view (XZ: yaw 0, pitch 0) a drag of (−90, 0): yaw 45.
    assert!(s.set_plane("XZ"));
    assert!(s.orbit_by(-90.0, 0.0));
    assert_eq!(s.view().angles, Some([45.0, 0.0]));
    // The 3D preset is the isometric view.
    assert!(s.set_plane("3D"));
    assert_eq!(s.view().angles, Some([45.0, 35.264]));
    // set_view reads what view writes; angles alone choose the 3D view.
    assert!(s.set_plane("XY"));
    let v = s.set_view(&change(r#"{"angles":[30,20]}"#));
    assert_eq!(
        (v.plane.as_deref(), v.angles),
        (Some("3D"), Some([30.0, 20.0]))
    );
    assert_eq!(s.set_view(&s.view()), s.view());
    // A plane named with angles is that plane.
    let v = s.set_view(&change(r#"{"plane":"XZ","angles":[30,20]}"#));
    assert_eq!((v.plane.as_deref(), v.angles), (Some("XZ"), None));
}

const LATHE: &str = "G50 X120. Z60.;\nG00 X40. Z2.;\nG01 Z-30. F0.2;\nX80.;\nG00 X120. Z60.;";

/// Behaviour 10.18: the lathe's ZX view is its 3D view at yaw 0, pitch 0,
/// and a drag turns it as the mill's: (−60, 40) pixels give yaw 0 + 30 =
/// 30, pitch 0 + 20 = 20. Its 3D preset is the isometric view, angles
/// alone choose it, and the mill's planes stay refused. The face view XC
/// does not turn (no yaw and pitch of the lathe's space show it: its
/// screen's right is X, which the turn keeps upright).
#[test]
fn behaviour10_18_the_lathe_turns_from_zx_and_its_face_view_does_not() {
    let mut s = session(LATHE, r#"{"machine":"lathe"}"#);
    assert_eq!(s.view().plane.as_deref(), Some("ZX"));
    assert!(s.orbit_by(-60.0, 40.0));
    let v = s.view();
    assert_eq!(
        (v.plane.as_deref(), v.angles),
        (Some("3D"), Some([30.0, 20.0]))
    );
    assert!(s.scene().plane.is_lathe() && s.scene().plane.is_orbit());
    assert!(s.set_plane("3D"));
    assert_eq!(s.view().angles, Some([45.0, 35.264]));
    assert!(s.set_plane("ZX"));
    let v = s.set_view(&change(r#"{"angles":[10,5]}"#));
    assert_eq!(
        (v.plane.as_deref(), v.angles),
        (Some("3D"), Some([10.0, 5.0]))
    );
    assert!(!s.set_plane("XY"));
    assert!(s.set_plane("XC"));
    assert!(!s.orbit_by(30.0, 30.0));
    assert_eq!(s.view().plane.as_deref(), Some("XC"));
    // Drawn: the lathe's legend, and the triad names Z, X and C.
    s.set_view(&change(r#"{"plane":"3D","angles":[30,20]}"#));
    let mut svg = SvgSurface::new();
    let f = render::draw_scene(&mut svg, s.toolpath(), s.scene(), 700.0, 500.0);
    let out = svg.finish(f.width, f.height);
    assert!(out.contains("lathe · 3D · mm"), "{out}");
    for name in [">Z<", ">X<", ">C<"] {
        assert!(out.contains(name), "{name}");
    }
    // The path's box (X 40–120 as a diameter, Z −30–60) lies in the plot.
    let (lo, hi) = s.toolpath().bounds().unwrap();
    for c in 0..8 {
        let p = [0, 1, 2].map(|k| if c >> k & 1 == 0 { lo[k] } else { hi[k] });
        let (u, v) = f.projection.project(&p);
        let (x, y) = f.transform.to_screen(u, v);
        assert!(x >= f.plot.x - 1e-6 && x <= f.plot.right() + 1e-6, "{p:?}");
        assert!(y >= f.plot.y - 1e-6 && y <= f.plot.bottom() + 1e-6, "{p:?}");
    }
}

/// Behaviour 10.18 and 10.9: the lathe's 3D view goes into the document
/// and the links as the mill's, and a lathe session given them shows it.
#[test]
fn behaviour10_18_the_lathe_3d_view_goes_into_the_document_and_the_link() {
    let mut s = session(LATHE, r#"{"machine":"lathe"}"#);
    s.set_view(&change(r#"{"plane":"3D","angles":[30,20]}"#));
    let doc = s.document();
    let json: serde_json::Value = serde_json::from_str(&doc.to_json_pretty()).unwrap();
    assert_eq!(json["view"]["plane"], "3D");
    assert_eq!(json["view"]["angles"], serde_json::json!([30.0, 20.0]));
    let plain = share::encode_plain(&doc, false);
    assert!(plain.contains("plane=3D&angles=30,20"), "{plain}");
    let back = share::decode(&plain).unwrap().document;
    assert_eq!(back.view, doc.view);
    let mut t = session(LATHE, r#"{"machine":"lathe"}"#);
    t.set_view(&change(r#"{"plane":"3D","angles":[30,20]}"#));
    assert_eq!(t.scene().plane, s.scene().plane);
}

/// Behaviour 10.9: the document's view holds plane "3D" and `angles`
/// [yaw, pitch]; the plain link writes `plane=3D&angles=yaw,pitch`, the
/// compact link carries the same document, and both read back.
#[test]
fn behaviour10_9_the_3d_view_goes_into_the_document_and_the_link() {
    let mut s = square();
    s.orbit_by(20.0, -40.0);
    let doc = s.document();
    let json: serde_json::Value = serde_json::from_str(&doc.to_json_pretty()).unwrap();
    assert_eq!(json["view"]["plane"], "3D");
    assert_eq!(json["view"]["angles"], serde_json::json!([350.0, 70.0]));
    let plain = share::encode_plain(&doc, false);
    assert!(plain.contains("plane=3D&angles=350,70"), "{plain}");
    let back = share::decode(&plain).unwrap().document;
    assert_eq!(back.view, doc.view);
    let link = share::link(share::DEFAULT_BASE, &doc, false).unwrap();
    assert_eq!(share::decode(&link).unwrap().document, doc);
    // A session given the document's view shows the same view.
    let mut t = square();
    let v = doc.view.unwrap();
    t.set_view(&change(&format!(
        r#"{{"plane":"3D","angles":[{},{}]}}"#,
        v.angles.unwrap()[0],
        v.angles.unwrap()[1]
    )));
    assert_eq!(t.scene().plane, s.scene().plane);
    // A plane view writes no angles; plane=3D without them is isometric.
    assert!(!share::encode_plain(&square().document(), false).contains("angles"));
    let iso = share::decode("program=G01X1.&plane=3D").unwrap().document;
    assert_eq!(iso.view.unwrap().angles, None);
    // Out of range angles are refused.
    assert!(share::decode("program=G01X1.&plane=3D&angles=0,95").is_err());
    assert!(share::decode("program=G01X1.&plane=3D&angles=1").is_err());
}

/// Behaviour 10.8: a turned view is another drawing for the kept pixel
/// layer (its key changes with the angles), and a moving frame of the 3D
/// view has a key of its own (its large paths may be a sample).
#[test]
fn behaviour10_8_turned_views_and_their_samples_are_other_layers() {
    let mut s = square();
    s.set_plane("3D");
    let key = s.ask_frame(300, 200, 1.0).key;
    assert_ne!(s.ask_moving_frame(300, 200, 1.0).key, key);
    s.orbit_by(2.0, 0.0);
    assert_ne!(s.ask_frame(300, 200, 1.0).key, key);
    // The plane views' moving frames keep the whole frame's key (a pan
    // moves its pixels).
    s.set_plane("XY");
    let key = s.ask_frame(300, 200, 1.0).key;
    assert_eq!(s.ask_moving_frame(300, 200, 1.0).key, key);
    // And an SVG of the 3D view names it in the legend.
    s.set_plane("3D");
    let mut svg = SvgSurface::new();
    let f = render::draw_scene(&mut svg, s.toolpath(), s.scene(), 600.0, 400.0);
    assert!(svg.finish(f.width, f.height).contains("mill · 3D · mm"));
}
