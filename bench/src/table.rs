//! Aligned plain-text tables for the terminal: text columns left-aligned, figures right-aligned,
//! and the number formats every figure of the report uses.

pub enum Row {
    Cells(Vec<String>),
    /// A horizontal rule, to set the summary rows apart.
    Rule,
}

pub struct Table {
    headers: Vec<String>,
    /// How many leading columns are text (left-aligned); the rest are figures.
    text_columns: usize,
    rows: Vec<Row>,
}

impl Table {
    pub fn new(headers: &[&str], text_columns: usize) -> Table {
        Table {
            headers: headers.iter().map(|h| h.to_string()).collect(),
            text_columns,
            rows: Vec::new(),
        }
    }

    pub fn row(&mut self, cells: Vec<String>) {
        debug_assert_eq!(cells.len(), self.headers.len());
        self.rows.push(Row::Cells(cells));
    }

    pub fn rule(&mut self) {
        self.rows.push(Row::Rule);
    }

    pub fn render(&self) -> String {
        let mut widths: Vec<usize> = self.headers.iter().map(|h| h.chars().count()).collect();
        for row in &self.rows {
            if let Row::Cells(cells) = row {
                for (w, c) in widths.iter_mut().zip(cells) {
                    *w = (*w).max(c.chars().count());
                }
            }
        }
        let line = |cells: &[String]| {
            let parts: Vec<String> = cells
                .iter()
                .zip(&widths)
                .enumerate()
                .map(|(i, (c, &w))| {
                    if i < self.text_columns {
                        format!("{c:<w$}")
                    } else {
                        format!("{c:>w$}")
                    }
                })
                .collect();
            parts.join("  ").trim_end().to_string()
        };
        let total = widths.iter().sum::<usize>() + 2 * widths.len().saturating_sub(1);
        let mut out = vec![line(&self.headers), "-".repeat(total)];
        for row in &self.rows {
            out.push(match row {
                Row::Cells(cells) => line(cells),
                Row::Rule => "-".repeat(total),
            });
        }
        out.join("\n")
    }
}

/// What an empty figure shows (not measured, or not meaningful such as the peer's steps).
pub const NONE: &str = "—";

/// Milliseconds: whole above 100, one decimal below.
pub fn ms(v: Option<f64>) -> String {
    match v {
        Some(v) if v >= 100.0 => format!("{v:.0}"),
        Some(v) => format!("{v:.1}"),
        None => NONE.into(),
    }
}

/// A metric (coherence, completeness, histogram), to four significant digits.
pub fn metric(v: Option<f64>) -> String {
    match v {
        Some(0.0) => "0".into(),
        Some(v) => {
            let digits = (3 - v.abs().log10().floor() as i32).clamp(0, 8) as usize;
            format!("{v:.digits$}")
        }
        None => NONE.into(),
    }
}

/// A flat fraction (0..1), to three decimals.
pub fn flat(v: Option<f64>) -> String {
    v.map_or(NONE.into(), |v| format!("{v:.3}"))
}

/// A ratio method/peer, two significant digits at least.
pub fn ratio(v: Option<f64>) -> String {
    match v {
        Some(v) if v < 0.1 => format!("{v:.3}"),
        Some(v) => format!("{v:.2}"),
        None => NONE.into(),
    }
}

pub fn count(v: Option<f64>) -> String {
    v.map_or(NONE.into(), |v| {
        if v.fract() == 0.0 {
            format!("{v:.0}")
        } else {
            format!("{v:.1}")
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_line_up() {
        let mut t = Table::new(&["name", "ms"], 1);
        t.row(vec!["a".into(), "1.5".into()]);
        t.rule();
        t.row(vec!["longer".into(), "123".into()]);
        assert_eq!(
            t.render(),
            "name     ms\n-----------\na       1.5\n-----------\nlonger  123"
        );
    }

    #[test]
    fn number_formats() {
        assert_eq!(ms(Some(1234.4)), "1234");
        assert_eq!(ms(Some(12.34)), "12.3");
        assert_eq!(metric(Some(0.0123456)), "0.01235");
        assert_eq!(metric(Some(0.5)), "0.5000");
        assert_eq!(ratio(Some(0.05)), "0.050");
        assert_eq!(ratio(Some(2.0)), "2.00");
        assert_eq!(count(Some(12.0)), "12");
        assert_eq!(ms(None), NONE);
    }
}
