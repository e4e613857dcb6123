//! `similarity.html`: the ranked pairs, then the matching passages of
//! the leading pairs side by side.

use std::fmt::Write as _;

use super::{CONTEXT_LINES, DETAILED, Report, Texts, count, detailed, percent};
use crate::grade::markup::html as escape;

/// Styles for the page: those of the grade report, with two code
/// columns and highlighted matches.
const STYLE: &str = "body{font-family:system-ui,sans-serif;margin:2em;max-width:110em}\
table{border-collapse:collapse;margin:.5em 0}td,th{padding:.25em .75em;text-align:left;\
border-bottom:1px solid #8884}td.num{text-align:right}.ok{color:#197a32}.fail{color:#b3261e}\
.flag{color:#b3261e;font-weight:600}small{color:#888}\
.sides{display:grid;grid-template-columns:1fr 1fr;gap:1em;margin:.5em 0 1.5em}.sides>div{min-width:0}\
.sides h4{margin:.25em 0;font-weight:600}\
pre{background:#8881;padding:.75em;overflow-x:auto;margin:0;font-size:.85em;line-height:1.35}\
pre .n{display:inline-block;width:3.5em;color:#888;user-select:none}\
pre .gap{color:#888;font-style:italic}\
mark{background:#f4c43066;color:inherit;border-radius:2px}";

/// The whole page.
pub(super) fn page(report: &Report, texts: &[Texts]) -> String {
    let mut html = String::new();
    let class = report.class.file_name().map_or_else(
        || report.class.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    let flagged = report.pairs.iter().filter(|p| p.flagged).count();
    let _ = writeln!(
        html,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <title>Similarity: {class}</title><style>{STYLE}</style></head><body>\n\
         <h1>Similarity: {class}</h1>\n\
         <p>{members} members, {pairs}, {files} compared with {engine} \
         (winnowing over tokens; names, comments and layout ignored; the course's stubs excluded). \
         A pair's score is the larger of the two shares: the part of a member's own code that \
         matches the other's. <span class=\"{class_flag}\">{flagged} at or above {threshold}</span>.</p>",
        class = escape(&class),
        members = report.members.len(),
        pairs = count(report.pairs.len(), "pair"),
        files = count(report.files.len(), "task file"),
        engine = escape(&report.engine),
        class_flag = if flagged > 0 { "flag" } else { "ok" },
        flagged = count(flagged, "pair"),
        threshold = percent(report.threshold),
    );
    html.push_str(
        "<table><tr><th>rank</th><th>members</th><th>score</th><th>shares</th>\
         <th>files alike</th><th></th></tr>\n",
    );
    let ranks: Vec<usize> = detailed(report).map(|p| p.rank).collect();
    for pair in &report.pairs {
        let names = format!("{} ↔ {}", escape(&pair.a), escape(&pair.b));
        let names = if ranks.contains(&pair.rank) {
            format!("<a href=\"#pair-{}\">{names}</a>", pair.rank)
        } else {
            names
        };
        let _ = writeln!(
            html,
            "<tr><td class=\"num\">{}</td><td>{names}</td><td class=\"num\">{}</td>\
             <td class=\"num\">{} / {}</td><td class=\"num\">{}</td><td>{}</td></tr>",
            pair.rank,
            percent(pair.score),
            percent(pair.shares[0]),
            percent(pair.shares[1]),
            pair.files.len(),
            if pair.flagged {
                "<span class=\"flag\">flagged</span>"
            } else {
                ""
            }
        );
    }
    html.push_str("</table>\n");
    if report.pairs.iter().filter(|p| p.score > 0.0).count() > ranks.len() {
        let _ = writeln!(
            html,
            "<p>The passages of the first {DETAILED} pairs follow; <code>similarity.json</code> \
             holds every pair's matches.</p>"
        );
    }
    let index = |name: &str| report.members.iter().position(|m| m == name);
    for pair in detailed(report) {
        let _ = writeln!(
            html,
            "<h2 id=\"pair-{rank}\">{rank}. {a} ↔ {b}: {score}{flag}</h2>\n\
             <p>{a}: {sa} of its code ({ma} of {ta} tokens) matches; {b}: {sb} ({mb} of {tb}).</p>",
            rank = pair.rank,
            a = escape(&pair.a),
            b = escape(&pair.b),
            score = percent(pair.score),
            flag = if pair.flagged {
                " <span class=\"flag\">flagged</span>"
            } else {
                ""
            },
            sa = percent(pair.shares[0]),
            sb = percent(pair.shares[1]),
            ma = pair.matched[0],
            ta = pair.tokens[0],
            mb = pair.matched[1],
            tb = pair.tokens[1],
        );
        let (Some(ia), Some(ib)) = (index(&pair.a), index(&pair.b)) else {
            continue;
        };
        for file in &pair.files {
            let _ = writeln!(
                html,
                "<h3><code>{}</code> <small>{} / {}</small></h3>\n<div class=\"sides\">",
                escape(&file.path.display().to_string()),
                percent(file.shares[0]),
                percent(file.shares[1]),
            );
            for (side, (member, name)) in [(ia, &pair.a), (ib, &pair.b)].into_iter().enumerate() {
                let text = texts[member].get(&file.path).map_or("", String::as_str);
                let _ = writeln!(
                    html,
                    "<div><h4>{}</h4>{}</div>",
                    escape(name),
                    passages(text, &file.ranges[side])
                );
            }
            html.push_str("</div>\n");
        }
    }
    html.push_str("</body></html>\n");
    html
}

/// `text` as a `<pre>` with line numbers, the byte `ranges` highlighted,
/// and only the lines near a highlight kept (the others are counted).
fn passages(text: &str, ranges: &[[usize; 2]]) -> String {
    // Ranges on char boundaries, sorted, within the text.
    let fix = |mut i: usize| {
        i = i.min(text.len());
        while !text.is_char_boundary(i) {
            i -= 1;
        }
        i
    };
    let mut ranges: Vec<(usize, usize)> = ranges
        .iter()
        .map(|[s, e]| (fix(*s), fix(*e)))
        .filter(|(s, e)| s < e)
        .collect();
    ranges.sort_unstable();
    let mut lines = Vec::new();
    let mut start = 0;
    for line in text.split_inclusive('\n') {
        lines.push((start, start + line.trim_end_matches('\n').len()));
        start += line.len();
    }
    let marked: Vec<bool> = lines
        .iter()
        .map(|&(s, e)| ranges.iter().any(|&(rs, re)| rs < e.max(s + 1) && re > s))
        .collect();
    let keep: Vec<bool> = (0..lines.len())
        .map(|i| {
            let from = i.saturating_sub(CONTEXT_LINES);
            let to = (i + CONTEXT_LINES + 1).min(lines.len());
            marked[from..to].iter().any(|&m| m)
        })
        .collect();
    let mut html = String::from("<pre>");
    let mut skipped = 0;
    let gap = |html: &mut String, skipped: &mut usize| {
        if *skipped > 0 {
            let _ = writeln!(
                html,
                "<span class=\"gap\">   ⋯ {} line{} without a match</span>",
                skipped,
                if *skipped == 1 { "" } else { "s" }
            );
            *skipped = 0;
        }
    };
    for (i, &(s, e)) in lines.iter().enumerate() {
        if !keep[i] {
            skipped += 1;
            continue;
        }
        gap(&mut html, &mut skipped);
        let _ = write!(html, "<span class=\"n\">{}</span>", i + 1);
        let mut at = s;
        for &(rs, re) in &ranges {
            let (rs, re) = (rs.max(s), re.min(e));
            if rs >= re || re <= at {
                continue;
            }
            let rs = rs.max(at);
            html.push_str(&escape(&text[at..rs]));
            let _ = write!(html, "<mark>{}</mark>", escape(&text[rs..re]));
            at = re;
        }
        html.push_str(&escape(&text[at..e]));
        html.push('\n');
    }
    gap(&mut html, &mut skipped);
    html.push_str("</pre>");
    html
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn passages_highlight_ranges_and_fold_lines_far_from_them() {
        let text: String = (1..=12).map(|i| format!("line {i} <x>\n")).collect();
        let start = text.find("line 6").unwrap();
        let html = passages(&text, &[[start, start + 6]]);
        assert!(html.contains("<mark>line 6</mark> &lt;x&gt;"), "{html}");
        assert!(html.contains("⋯ 3 lines without a match"), "{html}");
        assert!(html.contains("⋯ 4 lines without a match"), "{html}");
        assert!(!html.contains("line 3 "), "{html}");
        assert!(html.contains("line 4 "), "{html}");
    }

    #[test]
    fn a_range_across_lines_is_highlighted_on_each() {
        let text = "fn a() {\n    b();\n}\n";
        let html = passages(text, &[[3, 15]]);
        assert!(html.contains("fn <mark>a() {</mark>"), "{html}");
        assert!(html.contains("<mark>    b(</mark>);"), "{html}");
    }

    #[test]
    fn escape_covers_markup_and_quotes() {
        assert_eq!(
            escape("<a href=\"x\">&'"),
            "&lt;a href=&quot;x&quot;&gt;&amp;&apos;"
        );
    }
}
