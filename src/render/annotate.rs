//! What is drawn around the paths: the grid, the axes through the origin,
//! the scale bar and the legend, placed so that no label covers another.

use super::*;

/// The grid lines' world spacing for a transform.
pub fn grid_step(t: &Transform) -> f64 {
    nice_step(MIN_GRID_PX / t.scale)
}

pub(super) fn draw_grid(s: &mut impl Surface, f: &Frame) {
    let t = &f.transform;
    let whole = Rect::new(0.0, 0.0, f.width, f.height);
    let seen = t.visible(whole);
    let step = grid_step(t);
    let decimals = view::decimals_for(step);
    let us = multiples(seen.min_u, seen.max_u, step);
    let vs = multiples(seen.min_v, seen.max_v, step);
    s.begin_group("grid");
    s.begin_path(&f.theme.grid());
    for &u in &us {
        let (x, _) = t.to_screen(u, 0.0);
        let x = crisp(x);
        s.move_to(x, 0.0);
        s.line_to(x, f.height);
    }
    for &v in &vs {
        let (_, y) = t.to_screen(0.0, v);
        let y = crisp(y);
        s.move_to(0.0, y);
        s.line_to(f.width, y);
    }
    s.stroke();
    // Labels on every line that leaves room for them, along the bottom and
    // the left edge.
    let widest = us
        .iter()
        .chain(vs.iter())
        .map(|v| view::format_number(*v, decimals).chars().count())
        .max()
        .unwrap_or(1) as f64;
    let label_px = widest * style::TICK_FONT.size * 0.62 + 10.0;
    let every = ((label_px / (step * t.scale)).ceil() as i64).max(1);
    for &u in &us {
        if index_of(u, step) % every != 0 {
            continue;
        }
        let (x, _) = t.to_screen(u, 0.0);
        if x < MARGIN.0 + 4.0 || x > f.width - 16.0 {
            continue;
        }
        let text = view::format_number(u, decimals);
        s.fill_text(&text, x, f.height - 8.0, &f.theme.tick_font());
    }
    let every_v = ((style::TICK_FONT.size * 2.0 / (step * t.scale)).ceil() as i64).max(1);
    for &v in &vs {
        if index_of(v, step) % every_v != 0 {
            continue;
        }
        let (_, y) = t.to_screen(0.0, v);
        if y < 20.0 || y > f.height - 30.0 {
            continue;
        }
        let text = view::format_number(v, decimals);
        let font = Font {
            align: Align::End,
            ..f.theme.tick_font()
        };
        s.fill_text(&text, MARGIN.0 - 8.0, y + 4.0, &font);
    }
    s.end_group();
}

/// Multiples of `step` in `[min, max]`, at most a few thousand.
fn multiples(min: f64, max: f64, step: f64) -> Vec<f64> {
    if !(min.is_finite() && max.is_finite() && step > 0.0) {
        return Vec::new();
    }
    let first = (min / step).ceil() as i64;
    let last = (max / step).floor() as i64;
    if last < first || last - first > 4000 {
        return Vec::new();
    }
    (first..=last).map(|i| i as f64 * step).collect()
}

fn index_of(v: f64, step: f64) -> i64 {
    (v / step).round() as i64
}

/// The approximate box of a label (no text metrics on an SVG surface).
fn text_box(text: &str, x: f64, y: f64, font: &Font) -> Rect {
    let w = text.chars().count() as f64 * font.size * 0.62;
    let left = match font.align {
        Align::Start => x,
        Align::Middle => x - w / 2.0,
        Align::End => x - w,
    };
    Rect::new(left, y - font.size, w, font.size * 1.3)
}

/// The first of `spots` (anchor and font) where a label overlaps none of
/// `taken`, else the first.
fn free_spot(text: &str, spots: &[(f64, f64, Font)], taken: &[Rect]) -> Option<(f64, f64, Font)> {
    spots
        .iter()
        .copied()
        .find(|(x, y, font)| {
            !taken
                .iter()
                .any(|r| text_box(text, *x, *y, font).intersects(r))
        })
        .or_else(|| spots.first().copied())
}

/// `v` limited to `[lo, hi]`, preferring `lo` when the range is empty (on
/// tiny surfaces); unlike `f64::clamp` it never panics.
fn clamp(v: f64, lo: f64, hi: f64) -> f64 {
    v.min(hi).max(lo)
}

/// Half-pixel alignment keeps one-pixel lines sharp.
fn crisp(v: f64) -> f64 {
    v.floor() + 0.5
}

pub(super) fn draw_axes(s: &mut impl Surface, f: &Frame) {
    let t = &f.transform;
    let (x0, y0) = t.to_screen(0.0, 0.0);
    let (h_name, v_name) = f.plane.axis_names();
    s.begin_group("axes");
    let inside_x = (0.0..=f.width).contains(&x0);
    let inside_y = (0.0..=f.height).contains(&y0);
    if inside_x {
        s.begin_path(&f.theme.axis());
        s.move_to(crisp(x0), 0.0);
        s.line_to(crisp(x0), f.height);
        s.stroke();
    }
    if inside_y {
        let stroke = if f.plane.has_centre_line() {
            f.theme.centre()
        } else {
            f.theme.axis()
        };
        s.begin_path(&stroke);
        s.move_to(0.0, crisp(y0));
        s.line_to(f.width, crisp(y0));
        s.stroke();
    }
    let bold = Font {
        bold: true,
        ..f.theme.label_font()
    };
    // Axis names sit at the positive ends of the axes (at the surface's
    // edge when the origin is off it), moved aside from the legend and the
    // scale bar.
    let mut taken = vec![f.legend];
    if let Some((area, _)) = f.scale_bar() {
        taken.push(area);
    }
    let right = Font {
        align: Align::End,
        ..bold
    };
    let edge = f.width - 8.0;
    let y = clamp(y0, 30.0, f.height - 24.0);
    let mut h_spots = vec![(edge, y - 6.0, right), (edge, y + 16.0, right)];
    if let Some((area, _)) = f.scale_bar() {
        h_spots.push((area.x - 8.0, y - 6.0, right));
    }
    if let Some((x, y, font)) = free_spot(h_name, &h_spots, &taken) {
        s.fill_text(h_name, x, y, &font);
    }
    let x = clamp(x0, MARGIN.0, f.width - 40.0);
    let v_spots = [
        (x + 6.0, 16.0, bold),
        (x + 6.0, f.legend.bottom() + 16.0, bold),
        (x - 6.0, 16.0, right),
    ];
    if let Some((x, y, font)) = free_spot(v_name, &v_spots, &taken) {
        s.fill_text(v_name, x, y, &font);
    }
    if f.plane.has_centre_line() && inside_y {
        let font = Font {
            color: f.theme.centre,
            ..f.theme.label_font()
        };
        s.fill_text("centre line", MARGIN.0 + 6.0, y0 - 6.0, &font);
    }
    s.end_group();
}

fn units_name(tp: &Toolpath) -> &'static str {
    match tp.units {
        crate::Units::Mm => "mm",
        crate::Units::Inch => "in",
    }
}

pub(super) fn draw_scale_bar(s: &mut impl Surface, f: &Frame, tp: &Toolpath) {
    let Some((area, length)) = f.scale_bar() else {
        return;
    };
    let (left, right) = (area.x + 6.0, area.right() - 6.0);
    let y = area.y + 20.0;
    s.begin_group("scale");
    s.fill_rect(area, f.theme.scale_fill, None);
    s.begin_path(&f.theme.scale());
    s.move_to(left, y - 5.0);
    s.line_to(left, y);
    s.line_to(right, y);
    s.line_to(right, y - 5.0);
    s.stroke();
    let text = format!(
        "{} {}",
        view::format_number(length, view::decimals_for(length)),
        units_name(tp)
    );
    let font = Font {
        align: Align::Middle,
        ..f.theme.label_font()
    };
    s.fill_text(&text, (left + right) / 2.0, y - 8.0, &font);
    s.end_group();
}

/// How many rows the legend has (the frame leaves room for them).
pub(super) fn legend_row_count(
    plane: Plane,
    t: &Theme,
    tool_row: bool,
    compact: bool,
    holes: bool,
) -> usize {
    legend_rows(plane, t, tool_row, compact, holes).len()
}

/// What a legend row shows beside its label.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Key {
    Line(Stroke),
    Arrow(Stroke),
    Tool,
    Hole,
}

fn legend_rows(
    plane: Plane,
    t: &Theme,
    tool_row: bool,
    compact: bool,
    holes: bool,
) -> Vec<(Key, &'static str)> {
    let mut rows = if compact {
        vec![
            (Key::Line(t.actual_feed()), "actual"),
            (Key::Line(t.programmed_feed()), "programmed"),
            (Key::Line(t.actual_rapid()), "rapid"),
            (Key::Arrow(t.arrow()), "offset"),
        ]
    } else {
        vec![
            (Key::Line(t.actual_feed()), "actual, feed"),
            (Key::Line(t.actual_rapid()), "actual, rapid"),
            (Key::Line(t.programmed_feed()), "programmed, feed"),
            (Key::Line(t.programmed_rapid()), "programmed, rapid"),
            (Key::Arrow(t.arrow()), "programmed → actual end"),
        ]
    };
    if plane.has_centre_line() {
        rows.push((
            Key::Line(t.centre()),
            if compact { "centre" } else { "centre line" },
        ));
    }
    rows.extend(super::holes::legend_row(holes, compact));
    if tool_row {
        rows.push((
            Key::Tool,
            if compact {
                "tool"
            } else {
                "tool at current block"
            },
        ));
    }
    rows
}

pub(super) fn draw_legend(s: &mut impl Surface, f: &Frame, tp: &Toolpath) {
    if !f.legend_shown {
        return;
    }
    let r = f.legend;
    let t = f.theme;
    s.begin_group("legend");
    s.fill_rect(r, t.legend_fill, Some(t.legend_border));
    let machine = match tp.machine {
        MachineKind::Mill => "mill",
        MachineKind::Lathe => "lathe",
    };
    // The title names the machine in both legends: an exported image is
    // read without the page around it.
    let title = format!("{machine} · {} · {}", f.plane.name(), units_name(tp));
    let label = t.label_font();
    let bold = Font {
        bold: true,
        ..label
    };
    let mut y = r.y + LEGEND_PAD + LEGEND_ROW - 4.0;
    s.fill_text(&title, r.x + LEGEND_PAD, y, &bold);
    for (key, text) in legend_rows(f.plane, t, f.tool_row, f.compact, f.holes) {
        y += LEGEND_ROW;
        let mid = y - 4.0;
        let (x0, x1) = (r.x + LEGEND_PAD, r.x + LEGEND_PAD + 30.0);
        match key {
            Key::Line(stroke) => {
                s.begin_path(&stroke);
                s.move_to(x0, mid);
                s.line_to(x1, mid);
                s.stroke();
            }
            Key::Arrow(stroke) => scene::arrow(s, &stroke, (x0 + 4.0, mid), (x1, mid)),
            Key::Tool => scene::tool_symbol(s, t, (x0 + 15.0, mid)),
            Key::Hole => super::holes::hole_symbol(s, f, (x0 + 15.0, mid)),
        }
        s.fill_text(text, r.x + LEGEND_PAD + 38.0, y, &label);
    }
    s.end_group();
}
