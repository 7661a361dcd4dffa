//! Colours, line widths and dashes of the drawing. Hue says the kind of
//! motion (blue feed, orange rapid); the programmed path is a lighter tint,
//! thin and dashed, the actual path a dark tint, solid and wider, so the two
//! stay apart where they run side by side and where they coincide.
//!
//! The browser end-to-end tests look for the path colours in screenshots
//! (`tests/e2e/`); change them there too.

/// How a line is stroked.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stroke {
    /// CSS colour (`#rrggbb`).
    pub color: &'static str,
    /// Width in CSS pixels.
    pub width: f64,
    /// Dash pattern in CSS pixels (empty: solid).
    pub dash: &'static [f64],
}

/// Horizontal alignment of a text about its anchor point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Align {
    /// The text starts at the anchor.
    Start,
    /// The text is centred on the anchor.
    Middle,
    /// The text ends at the anchor.
    End,
}

/// How a text is drawn; its anchor's y is the alphabetic baseline.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Font {
    /// Size in CSS pixels.
    pub size: f64,
    /// CSS colour.
    pub color: &'static str,
    /// Alignment about the anchor.
    pub align: Align,
    /// Bold weight.
    pub bold: bool,
}

/// The font family of every label.
pub const FONT_FAMILY: &str = "system-ui, -apple-system, 'Segoe UI', Roboto, sans-serif";

/// Page background.
pub const BACKGROUND: &str = "#ffffff";
/// Grid lines.
pub const GRID: &str = "#e9ecef";
/// Axes through the origin.
pub const AXIS: &str = "#868e96";
/// Tick labels, captions, legend text.
pub const LABEL: &str = "#343a40";
/// The lathe's centre line.
pub const CENTRE_LINE: &str = "#5f3dc4";
/// Legend box fill and border.
pub const LEGEND_FILL: &str = "#ffffff";
/// Legend box border.
pub const LEGEND_BORDER: &str = "#ced4da";
/// Behind the scale bar, so grid lines do not run through its label.
pub const SCALE_FILL: &str = "rgba(255, 255, 255, 0.85)";

/// Actual path, feed moves (G01, arcs, offset motion in G01).
pub const ACTUAL_FEED: Stroke = Stroke {
    color: "#1c4fd8",
    width: 2.25,
    dash: &[],
};
/// Actual path, rapid moves (G00, offset motion in G00).
pub const ACTUAL_RAPID: Stroke = Stroke {
    color: "#d9480f",
    width: 2.25,
    dash: &[],
};
/// Programmed path, feed moves.
pub const PROGRAMMED_FEED: Stroke = Stroke {
    color: "#4dabf7",
    width: 1.5,
    dash: &[6.0, 4.0],
};
/// Programmed path, rapid moves.
pub const PROGRAMMED_RAPID: Stroke = Stroke {
    color: "#ffa94d",
    width: 1.5,
    dash: &[6.0, 4.0],
};
/// Grid lines.
pub const GRID_STROKE: Stroke = Stroke {
    color: GRID,
    width: 1.0,
    dash: &[],
};
/// Axes.
pub const AXIS_STROKE: Stroke = Stroke {
    color: AXIS,
    width: 1.25,
    dash: &[],
};
/// The lathe's centre line: long dash, short dash, as on a drawing.
pub const CENTRE_STROKE: Stroke = Stroke {
    color: CENTRE_LINE,
    width: 1.25,
    dash: &[14.0, 3.0, 3.0, 3.0],
};
/// The scale bar.
pub const SCALE_STROKE: Stroke = Stroke {
    color: LABEL,
    width: 1.5,
    dash: &[],
};

/// Tick labels.
pub const TICK_FONT: Font = Font {
    size: 11.0,
    color: "#6c757d",
    align: Align::Middle,
    bold: false,
};
/// Legend, scale and caption text.
pub const LABEL_FONT: Font = Font {
    size: 12.0,
    color: LABEL,
    align: Align::Start,
    bold: false,
};
