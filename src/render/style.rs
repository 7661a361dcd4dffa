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

/// The colours of one colour scheme. The page passes `light` or `dark`
/// (from `prefers-color-scheme`) so the canvas matches the page around it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Theme {
    /// `light` or `dark`.
    pub name: &'static str,
    /// Background of the drawing.
    pub background: &'static str,
    /// Grid lines.
    pub grid: &'static str,
    /// Axes through the origin.
    pub axis: &'static str,
    /// Captions, legend text, scale bar.
    pub label: &'static str,
    /// Tick labels.
    pub tick: &'static str,
    /// The lathe's centre line.
    pub centre: &'static str,
    /// Legend box fill.
    pub legend_fill: &'static str,
    /// Legend box border.
    pub legend_border: &'static str,
    /// Behind the scale bar.
    pub scale_fill: &'static str,
    /// Actual path, feed moves.
    pub actual_feed: &'static str,
    /// Actual path, rapid moves.
    pub actual_rapid: &'static str,
    /// Programmed path, feed moves.
    pub programmed_feed: &'static str,
    /// Programmed path, rapid moves.
    pub programmed_rapid: &'static str,
    /// Moves after the current block (not run yet when stepping).
    pub ghost: &'static str,
    /// The arrows from programmed to actual end points.
    pub arrow: &'static str,
    /// The tool marker at the current block's actual position.
    pub tool: &'static str,
    /// Under the current block's moves.
    pub highlight: &'static str,
    /// The band the cutter sweeps (behaviour 16.20), under the paths.
    pub swept: &'static str,
}

/// The light scheme (the constants above).
pub const LIGHT: Theme = Theme {
    name: "light",
    background: BACKGROUND,
    grid: GRID,
    axis: AXIS,
    label: LABEL,
    tick: "#6c757d",
    centre: CENTRE_LINE,
    legend_fill: LEGEND_FILL,
    legend_border: LEGEND_BORDER,
    scale_fill: SCALE_FILL,
    actual_feed: ACTUAL_FEED.color,
    actual_rapid: ACTUAL_RAPID.color,
    programmed_feed: PROGRAMMED_FEED.color,
    programmed_rapid: PROGRAMMED_RAPID.color,
    ghost: "#ced4da",
    arrow: "#c2255c",
    tool: "#2b8a3e",
    highlight: "rgba(252, 196, 25, 0.55)",
    swept: "rgba(43, 138, 62, 0.22)",
};

/// The dark scheme: the same hues, lighter, on a dark background.
pub const DARK: Theme = Theme {
    name: "dark",
    background: "#16181d",
    grid: "#2a2d35",
    axis: "#7d8590",
    label: "#e6e8eb",
    tick: "#a3aab3",
    centre: "#b197fc",
    legend_fill: "#1f2229",
    legend_border: "#474d57",
    scale_fill: "rgba(22, 24, 29, 0.85)",
    actual_feed: "#6ea8ff",
    actual_rapid: "#ff8c42",
    programmed_feed: "#a5d8ff",
    programmed_rapid: "#ffd8a8",
    ghost: "#3b404a",
    arrow: "#f783ac",
    tool: "#51cf66",
    highlight: "rgba(252, 196, 25, 0.35)",
    swept: "rgba(81, 207, 102, 0.22)",
};

impl Theme {
    /// `dark` or anything else (light).
    pub fn named(name: &str) -> &'static Theme {
        if name.eq_ignore_ascii_case("dark") {
            &DARK
        } else {
            &LIGHT
        }
    }

    fn with(stroke: Stroke, color: &'static str) -> Stroke {
        Stroke { color, ..stroke }
    }

    /// Actual path, feed moves.
    pub fn actual_feed(&self) -> Stroke {
        Self::with(ACTUAL_FEED, self.actual_feed)
    }
    /// Actual path, rapid moves.
    pub fn actual_rapid(&self) -> Stroke {
        Self::with(ACTUAL_RAPID, self.actual_rapid)
    }
    /// Programmed path, feed moves.
    pub fn programmed_feed(&self) -> Stroke {
        Self::with(PROGRAMMED_FEED, self.programmed_feed)
    }
    /// Programmed path, rapid moves.
    pub fn programmed_rapid(&self) -> Stroke {
        Self::with(PROGRAMMED_RAPID, self.programmed_rapid)
    }
    /// Moves not run yet.
    pub fn ghost(&self) -> Stroke {
        Stroke {
            color: self.ghost,
            width: 1.25,
            dash: &[],
        }
    }
    /// Offset arrows.
    pub fn arrow(&self) -> Stroke {
        Stroke {
            color: self.arrow,
            width: 1.5,
            dash: &[],
        }
    }
    /// Under the current block.
    pub fn highlight(&self) -> Stroke {
        Stroke {
            color: self.highlight,
            width: 9.0,
            dash: &[],
        }
    }
    /// Grid lines.
    pub fn grid(&self) -> Stroke {
        Self::with(GRID_STROKE, self.grid)
    }
    /// Axes.
    pub fn axis(&self) -> Stroke {
        Self::with(AXIS_STROKE, self.axis)
    }
    /// Centre line.
    pub fn centre(&self) -> Stroke {
        Self::with(CENTRE_STROKE, self.centre)
    }
    /// Scale bar.
    pub fn scale(&self) -> Stroke {
        Self::with(SCALE_STROKE, self.label)
    }
    /// Tick labels.
    pub fn tick_font(&self) -> Font {
        Font {
            color: self.tick,
            ..TICK_FONT
        }
    }
    /// Legend, scale and caption text.
    pub fn label_font(&self) -> Font {
        Font {
            color: self.label,
            ..LABEL_FONT
        }
    }
}
