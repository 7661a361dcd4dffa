//! Canvas backend (wasm only): draws through an OffscreenCanvas 2D context
//! that the page transferred to its worker, so the path's vertices stay in
//! wasm memory and only drawing calls cross into the browser.

use js_sys::Array;
use wasm_bindgen::JsValue;
use web_sys::OffscreenCanvasRenderingContext2d;

use super::style::{Align, FONT_FAMILY, Font, Stroke};
use super::{Rect, Surface};

/// A 2D context seen as a [`Surface`] in CSS pixels; the caller sets the
/// device-pixel transform.
pub struct CanvasSurface<'a> {
    ctx: &'a OffscreenCanvasRenderingContext2d,
    font: String,
}

impl<'a> CanvasSurface<'a> {
    /// Wraps a context.
    pub fn new(ctx: &'a OffscreenCanvasRenderingContext2d) -> CanvasSurface<'a> {
        ctx.set_line_cap("round");
        ctx.set_line_join("round");
        CanvasSurface {
            ctx,
            font: String::new(),
        }
    }
}

impl Surface for CanvasSurface<'_> {
    fn clear(&mut self, width: f64, height: f64, color: &str) {
        self.ctx.set_fill_style_str(color);
        self.ctx.fill_rect(0.0, 0.0, width, height);
    }

    fn begin_path(&mut self, stroke: &Stroke) {
        self.ctx.set_stroke_style_str(stroke.color);
        self.ctx.set_line_width(stroke.width);
        let dash: Array = stroke.dash.iter().map(|d| JsValue::from_f64(*d)).collect();
        // Only fails for negative or non-finite lengths, which the styles never use.
        let _ = self.ctx.set_line_dash(&dash);
        self.ctx.begin_path();
    }

    fn move_to(&mut self, x: f64, y: f64) {
        self.ctx.move_to(x, y);
    }

    fn line_to(&mut self, x: f64, y: f64) {
        self.ctx.line_to(x, y);
    }

    fn stroke(&mut self) {
        self.ctx.stroke();
    }

    fn fill_rect(&mut self, rect: Rect, fill: &str, border: Option<&str>) {
        self.ctx.set_fill_style_str(fill);
        self.ctx.fill_rect(rect.x, rect.y, rect.w, rect.h);
        if let Some(border) = border {
            self.ctx.set_stroke_style_str(border);
            self.ctx.set_line_width(1.0);
            let _ = self.ctx.set_line_dash(&Array::new());
            self.ctx
                .stroke_rect(rect.x + 0.5, rect.y + 0.5, rect.w - 1.0, rect.h - 1.0);
        }
    }

    fn fill_text(&mut self, text: &str, x: f64, y: f64, font: &Font) {
        let css = format!(
            "{}{}px {}",
            if font.bold { "bold " } else { "" },
            font.size,
            FONT_FAMILY
        );
        if css != self.font {
            self.ctx.set_font(&css);
            self.font = css;
        }
        self.ctx.set_text_align(match font.align {
            Align::Start => "start",
            Align::Middle => "center",
            Align::End => "end",
        });
        self.ctx.set_fill_style_str(font.color);
        // fillText only throws for non-finite coordinates; a label is skipped then.
        let _ = self.ctx.fill_text(text, x, y);
    }

    fn fill_polygon(&mut self, points: &[(f64, f64)], fill: &str) {
        let Some(((x0, y0), rest)) = points.split_first() else {
            return;
        };
        self.ctx.begin_path();
        self.ctx.move_to(*x0, *y0);
        for (x, y) in rest {
            self.ctx.line_to(*x, *y);
        }
        self.ctx.close_path();
        self.ctx.set_fill_style_str(fill);
        self.ctx.fill();
    }

    fn circle(&mut self, x: f64, y: f64, r: f64, fill: Option<&str>, stroke: Option<&Stroke>) {
        self.ctx.begin_path();
        // arc only throws for a negative radius.
        if self
            .ctx
            .arc(x, y, r.max(0.0), 0.0, std::f64::consts::TAU)
            .is_err()
        {
            return;
        }
        if let Some(fill) = fill {
            self.ctx.set_fill_style_str(fill);
            self.ctx.fill();
        }
        if let Some(stroke) = stroke {
            self.ctx.set_stroke_style_str(stroke.color);
            self.ctx.set_line_width(stroke.width);
            let _ = self.ctx.set_line_dash(&Array::new());
            self.ctx.stroke();
        }
    }
}
