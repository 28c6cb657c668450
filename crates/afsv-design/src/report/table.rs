//! Text tables of records: an aligned table with its ends shown ([`text`]) and numbers that
//! read plainly at any scale ([`number`]); the CLI prints them on a terminal.

use afsv_records::Record;

/// An aligned text table of `rec`: the header, the first and last `ends` rows, and a
/// `...` line between them when rows are left out. Numbers show 6 significant digits.
pub fn text(rec: &Record, ends: usize) -> String {
    let n = rec.len();
    let shown: Vec<usize> = if n <= 2 * ends {
        (0..n).collect()
    } else {
        (0..ends).chain(n - ends..n).collect()
    };
    let cells: Vec<Vec<String>> = rec
        .names()
        .iter()
        .map(|name| {
            let col = rec.column(name).unwrap_or_default();
            shown.iter().map(|&i| number(col[i])).collect()
        })
        .collect();
    let widths: Vec<usize> = rec
        .names()
        .iter()
        .zip(&cells)
        .map(|(h, c)| c.iter().map(String::len).max().unwrap_or(0).max(h.len()))
        .collect();
    let mut out = String::new();
    let line = |items: Vec<&str>, out: &mut String| {
        let parts: Vec<String> = items
            .iter()
            .zip(&widths)
            .map(|(s, w)| format!("{s:>w$}"))
            .collect();
        out.push_str(parts.join("  ").trim_end());
        out.push('\n');
    };
    line(rec.names().iter().map(String::as_str).collect(), &mut out);
    for k in 0..shown.len() {
        if k == ends && n > 2 * ends {
            out.push_str(&format!("... {} rows left out ...\n", n - 2 * ends));
        }
        line(cells.iter().map(|c| c[k].as_str()).collect(), &mut out);
    }
    out
}

/// A number with 6 significant digits, in plain notation between 1e-3 and 1e6 (tables and
/// study variables on a terminal: α_r = 1.6e-7 must not print as 0.0000).
pub fn number(v: f64) -> String {
    let a = v.abs();
    if v == 0.0 {
        "0".into()
    } else if (1e-3..1e6).contains(&a) {
        let decimals = (5 - a.log10().floor() as i32).max(0) as usize;
        let s = format!("{v:.decimals$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        format!("{v:.5e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_table_shows_its_ends_on_a_terminal() {
        let mut rec = Record::new();
        rec.push_column("n_cycles_per_m", (0..100).map(f64::from).collect())
            .unwrap();
        rec.push_column(
            "psd_m3",
            (0..100).map(|i| 1e-4 / (1.0 + f64::from(i))).collect(),
        )
        .unwrap();
        let t = text(&rec, 3);
        let lines: Vec<&str> = t.lines().collect();
        assert_eq!(lines.len(), 1 + 3 + 1 + 3, "{t}");
        assert!(lines[0].trim_start().starts_with("n_cycles_per_m"));
        assert!(lines[4].contains("94 rows left out"));
        assert!(lines[7].trim_start().starts_with("99"), "{t}");
        assert!(lines[7].contains("1.00000e-6"), "{t}");
    }

    #[test]
    fn numbers_read_plainly() {
        assert_eq!(number(0.0), "0");
        assert_eq!(number(123.456789), "123.457");
        assert_eq!(number(-0.5), "-0.5");
        assert_eq!(number(2.5e-7), "2.50000e-7");
        assert_eq!(number(150000.0), "150000");
    }
}
