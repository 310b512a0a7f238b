//! Figures that cannot flatter: every figure is kept as all of its runs (min / median /
//! max), paired with the reference it is to be read against, and the "how many robots"
//! figure is the largest N whose every smaller tried N passed too.

/// One measured quantity over repeated runs.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    pub name: String,
    pub unit: &'static str,
    /// One value per run, in run order.
    pub values: Vec<f64>,
    /// The name of the figure measured in the same run that this one is read against
    /// (the machine's own limit, a plain host server, …).
    pub reference: Option<String>,
}

/// min, median, max of a non-empty sample.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spread {
    pub min: f64,
    pub median: f64,
    pub max: f64,
}

/// p50 and p99 of round-trip samples (sorted in place; at least one).
pub fn p50_p99(samples: &mut [f64]) -> (f64, f64) {
    samples.sort_by(f64::total_cmp);
    let n = samples.len();
    (samples[n / 2], samples[n * 99 / 100])
}

impl Spread {
    pub fn of(values: &[f64]) -> Option<Spread> {
        let mut v: Vec<f64> = values.iter().copied().filter(|x| x.is_finite()).collect();
        if v.is_empty() {
            return None;
        }
        v.sort_by(f64::total_cmp);
        let n = v.len();
        let median = if n % 2 == 1 { v[n / 2] } else { (v[n / 2 - 1] + v[n / 2]) / 2.0 };
        Some(Spread { min: v[0], median, max: v[n - 1] })
    }
}

/// Collects the figures of several runs: the first run fixes the order, later runs
/// append their values to the figure of the same name.
#[derive(Debug, Default)]
pub struct Table {
    pub figures: Vec<Figure>,
}

impl Table {
    pub fn push(&mut self, name: &str, value: f64, unit: &'static str, reference: Option<&str>) {
        match self.figures.iter_mut().find(|f| f.name == name) {
            Some(f) => f.values.push(value),
            None => self.figures.push(Figure { name: name.to_string(), unit, values: vec![value], reference: reference.map(str::to_string) }),
        }
    }

    pub fn get(&self, name: &str) -> Option<&Figure> {
        self.figures.iter().find(|f| f.name == name)
    }
}

/// One tried robot count of the real-time sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Trial {
    pub robots: usize,
    /// Late frames, percent of all frames of all robots.
    pub late_pct: f64,
    /// How far the slowest robot ended behind real time, seconds (wall time of its run
    /// minus the robot time it ran).
    pub lag_s: f64,
}

/// Most late frames a passing trial may have, percent.
pub const MAX_LATE_PCT: f64 = 0.1;
/// Most a passing trial's slowest robot may lag behind real time: process start and
/// loading on a loaded 2-core machine stay well below it; a robot whose clock slips does not.
pub const MAX_LAG_S: f64 = 0.5;

impl Trial {
    pub fn passed(&self) -> bool {
        self.late_pct < MAX_LATE_PCT && self.lag_s <= MAX_LAG_S
    }
}

/// The largest robot count N such that every tried count ≤ N passed (0 if the smallest
/// failed). A pass at a larger N after a failure does not count: it is noise, not room.
pub fn largest_passing(trials: &[Trial]) -> usize {
    let mut sorted: Vec<&Trial> = trials.iter().collect();
    sorted.sort_by_key(|t| t.robots);
    let mut best = 0;
    for t in sorted {
        if !t.passed() {
            break;
        }
        best = t.robots;
    }
    best
}

fn fmt(v: f64) -> String {
    let a = v.abs();
    if a >= 1000.0 {
        format!("{v:.0}")
    } else if a >= 10.0 {
        format!("{v:.1}")
    } else {
        format!("{v:.2}")
    }
}

/// The figures as a Markdown table: min / median / max of the runs, and each figure's
/// reference (its median) with the ratio of the medians.
pub fn markdown(table: &Table) -> String {
    let mut s = String::from("| what | min | median | max | unit | same-run reference (median) | ratio |\n|---|---:|---:|---:|---|---|---:|\n");
    for f in &table.figures {
        let Some(sp) = Spread::of(&f.values) else { continue };
        let (rname, ratio) = match f.reference.as_deref().and_then(|r| table.get(r)).and_then(|r| Some((r, Spread::of(&r.values)?))) {
            Some((r, rs)) if rs.median != 0.0 => (format!("{}: {} {}", r.name, fmt(rs.median), r.unit), format!("{:.2}×", sp.median / rs.median)),
            _ => (String::new(), String::new()),
        };
        // A `|` inside a cell (|Δt − 32 ms|) would end the cell.
        let cell = |t: &str| t.replace('|', "\\|");
        s.push_str(&format!("| {} | {} | {} | {} | {} | {} | {} |\n", cell(&f.name), fmt(sp.min), fmt(sp.median), fmt(sp.max), f.unit, cell(&rname), ratio));
    }
    s
}

pub const BEGIN: &str = "<!-- bench:begin (cargo openr bench --readme README.md rewrites this part) -->";
pub const END: &str = "<!-- bench:end -->";

/// `text` with the part between [`BEGIN`] and [`END`] replaced by `body`; `None` when the
/// markers are missing or out of order (nothing is then written).
pub fn replace_section(text: &str, body: &str) -> Option<String> {
    let b = text.find(BEGIN)?;
    let e = text[b..].find(END)? + b;
    Some(format!("{}{BEGIN}\n{body}{}", &text[..b], &text[e..]))
}

/// The text between the markers of `text`, if they are there in order.
pub fn section(text: &str) -> Option<&str> {
    let b = text.find(BEGIN)? + BEGIN.len();
    let e = text[b..].find(END)? + b;
    Some(text[b..e].trim_start_matches('\n'))
}

/// A partial run (`--only`) written into an existing section: each row of `table` (as
/// [`markdown`] makes it) takes the place of the old row of the same figure, rows of
/// figures the old table lacks follow its last row, every other row and line stays; `note`
/// (what was measured again, when) is added after the table.
pub fn merge_rows(old: &str, table: &str, note: &str) -> String {
    let key = |line: &str| line.strip_prefix("| ").and_then(|r| r.split(" | ").next()).map(str::to_string);
    let fresh: Vec<(String, &str)> = table.lines().skip(2).filter_map(|l| Some((key(l)?, l))).collect();
    let mut used = vec![false; fresh.len()];
    let mut out: Vec<String> = Vec::new();
    let mut last_row = None;
    for line in old.lines() {
        let replaced = key(line).and_then(|k| fresh.iter().position(|(f, _)| *f == k));
        if let Some(i) = replaced {
            used[i] = true;
            out.push(fresh[i].1.to_string());
        } else {
            out.push(line.to_string());
        }
        if line.starts_with('|') {
            last_row = Some(out.len());
        }
    }
    let added: Vec<String> = fresh.iter().zip(&used).filter(|(_, u)| !**u).map(|((_, l), _)| l.to_string()).collect();
    let at = last_row.unwrap_or(out.len());
    let after = at + added.len();
    out.splice(at..at, added);
    out.splice(after..after, [String::new(), note.to_string()]);
    out.join("\n") + "\n"
}

#[cfg(test)]
mod tests {
    use super::*;

    fn t(robots: usize, late_pct: f64, lag_s: f64) -> Trial {
        Trial { robots, late_pct, lag_s }
    }

    #[test]
    fn a_partial_run_replaces_its_rows_and_keeps_the_others() {
        let old = "Measured 2026-12-01:\n\n| what | min |\n|---|---:|\n| a | 1 |\n| b | 2 |\n| c | 3 |\n\nLoaded machine.\n";
        let new = "| what | min |\n|---|---:|\n| b | 20 |\n| d | 40 |\n";
        let merged = merge_rows(old, new, "b, d: again on 2026-12-02.");
        assert_eq!(merged, "Measured 2026-12-01:\n\n| what | min |\n|---|---:|\n| a | 1 |\n| b | 20 |\n| c | 3 |\n| d | 40 |\n\nb, d: again on 2026-12-02.\n\nLoaded machine.\n");
        let text = format!("x\n{BEGIN}\n{old}{END}\ny\n");
        assert_eq!(section(&text), Some(old));
        assert_eq!(section("no markers"), None);
    }

    #[test]
    fn a_pass_after_a_failure_does_not_count() {
        // The run the issue saw: 1 passed, 2, 3, 4, 6 late, 8 passed — the answer is 1, not 8.
        let trials = [t(1, 0.0, 0.0), t(2, 0.2, 0.0), t(3, 1.3, 0.1), t(4, 0.5, 0.0), t(6, 0.9, 0.0), t(8, 0.0, 0.0)];
        assert_eq!(largest_passing(&trials), 1);
    }

    #[test]
    fn every_count_up_to_n_passing_gives_n_in_any_order() {
        let trials = [t(4, 0.05, 0.2), t(1, 0.0, 0.0), t(2, 0.0, 0.1), t(3, 0.09, 0.0), t(6, 0.1, 0.0)];
        assert_eq!(largest_passing(&trials), 4, "0.1% is not < 0.1%");
        assert_eq!(largest_passing(&[t(1, 0.3, 0.0)]), 0);
        assert_eq!(largest_passing(&[]), 0);
    }

    #[test]
    fn lag_behind_real_time_fails_a_trial_with_few_late_frames() {
        // 32 robots: clocks 8 s behind while the late count looked moderate.
        assert!(!t(32, 0.0, 8.0).passed());
        assert_eq!(largest_passing(&[t(1, 0.0, 0.1), t(2, 0.0, 0.6), t(3, 0.0, 0.0)]), 1);
    }

    #[test]
    fn spread_is_min_median_max_and_ignores_non_finite() {
        assert_eq!(Spread::of(&[3.0, 1.0, 2.0]), Some(Spread { min: 1.0, median: 2.0, max: 3.0 }));
        assert_eq!(Spread::of(&[4.0, 1.0, f64::NAN, 2.0, 3.0]).unwrap().median, 2.5);
        assert_eq!(Spread::of(&[f64::INFINITY]), None);
    }

    #[test]
    fn table_merges_runs_by_name_and_renders_ratios() {
        let mut tab = Table::default();
        for (a, r) in [(10.0, 5.0), (14.0, 6.0), (12.0, 4.0)] {
            tab.push("rtt", a, "µs", Some("raw"));
            tab.push("raw", r, "µs", None);
        }
        assert_eq!(tab.get("rtt").unwrap().values, vec![10.0, 14.0, 12.0]);
        let md = markdown(&tab);
        assert!(md.contains("| rtt | 10.0 | 12.0 | 14.0 | µs | raw: 5.00 µs | 2.40× |"), "{md}");
        assert!(md.contains("| raw | 4.00 | 5.00 | 6.00 | µs |  |  |"), "{md}");
        let mut tab = Table::default();
        tab.push("jitter |Δt − 32 ms| p50", 1.0, "µs", None);
        assert!(markdown(&tab).contains("| jitter \\|Δt − 32 ms\\| p50 | 1.00 |"), "{}", markdown(&tab));
    }

    #[test]
    fn readme_section_is_replaced_only_between_the_markers() {
        let text = format!("intro\n{BEGIN}\nold table\n{END}\nafter\n");
        let new = replace_section(&text, "new table\n").unwrap();
        assert_eq!(new, format!("intro\n{BEGIN}\nnew table\n{END}\nafter\n"));
        assert_eq!(replace_section("no markers", "x"), None);
        assert_eq!(replace_section(&format!("{END}\n{BEGIN}\n"), "x"), None);
    }
}
