//! Draws the SRDO timing of a fault-injection campaign
//! (`cargo run --example fault_injection -- --pairs FILE`): one point per
//! pair, the gap between its two frames against SRVT and the period since
//! the previous valid pair against SCT, with both limits drawn. The legal
//! pairs (accepted) and the pairs late on purpose (frame 2 after SRVT:
//! reported; frame 1 after SCT: the timeout reported, then the pair
//! accepted) are drawn apart.
//!
//! ```text
//! srdo_plot PAIRS.csv OUT.svg
//! ```

use std::collections::BTreeSet;
use std::process::ExitCode;

use plotters::prelude::*;

/// What the consumer did with a pair.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    Accepted,
    SrvtReported,
    SctReported,
}

/// One pair, in ticks of 100 µs.
struct Pair {
    gap: u64,
    period: u64,
    kind: Kind,
}

/// The campaign's limits and pairs.
struct Campaign {
    title: String,
    srvt: u64,
    sct: u64,
    pairs: Vec<Pair>,
}

fn parse(text: &str) -> Result<Campaign, String> {
    let mut lines = text.lines();
    let head = lines.next().ok_or("empty file")?;
    let field = |name: &str| -> Result<u64, String> {
        let at = head.find(name).ok_or(format!("no {name} in the header"))?;
        let rest = head[at + name.len()..].trim_start();
        let digits = rest
            .find(|c: char| !c.is_ascii_digit())
            .unwrap_or(rest.len());
        rest[..digits].parse().map_err(|_| format!("bad {name}"))
    };
    let (srvt, sct) = (field("srvt_ticks")?, field("sct_ticks")?);
    let title = head.trim_start_matches('#').trim().to_string();
    let mut pairs = Vec::new();
    for (n, line) in lines.enumerate().skip(1) {
        let mut f = line.split(',');
        let bad = || format!("line {}: {line}", n + 2);
        let gap = f.next().and_then(|s| s.parse().ok()).ok_or_else(bad)?;
        let period = f.next().and_then(|s| s.parse().ok()).ok_or_else(bad)?;
        let kind = match f.next().ok_or_else(bad)? {
            "" => Kind::Accepted,
            "srvt" => Kind::SrvtReported,
            "sct" => Kind::SctReported,
            _ => return Err(bad()),
        };
        pairs.push(Pair { gap, period, kind });
    }
    Ok(Campaign {
        title,
        srvt,
        sct,
        pairs,
    })
}

/// Side of the square, in pixels, that holds at most one mark of a kind.
const CELL: u32 = 8;

/// Ticks of 100 µs in ms.
fn ms(t: u64) -> f64 {
    t as f64 / 10.0
}

fn draw(c: &Campaign, out: &str) -> Result<(), Box<dyn std::error::Error>> {
    let max = |kind: Kind, f: fn(&Pair) -> u64| {
        c.pairs
            .iter()
            .filter(|p| p.kind == kind)
            .map(f)
            .max()
            .unwrap_or(0)
    };
    let count = |kind: Kind| c.pairs.iter().filter(|p| p.kind == kind).count();
    let x_max = ms(c.pairs.iter().map(|p| p.gap).max().unwrap_or(0).max(c.srvt)) * 1.1;
    let y_max = ms(c
        .pairs
        .iter()
        .map(|p| p.period)
        .max()
        .unwrap_or(0)
        .max(c.sct))
        * 1.15;

    let (w, h) = (900u32, 640u32);
    let root = SVGBackend::new(out, (w, h)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            format!("SRDO timing of {} pairs ({})", c.pairs.len(), c.title),
            ("sans-serif", 15),
        )
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(60)
        .build_cartesian_2d(0f64..x_max, 0f64..y_max)?;
    chart
        .configure_mesh()
        .x_desc("gap between frame 1 and frame 2 (ms)")
        .y_desc("period since frame 1 of the previous valid pair (ms)")
        .light_line_style(WHITE.mix(0.0))
        .draw()?;

    // One mark per cell of CELL x CELL pixels (a mark is about that size):
    // a mark per pair would only repeat marks already drawn and make the
    // file megabytes long.
    let points = |kind: Kind| -> Vec<(f64, f64)> {
        let mut seen = BTreeSet::new();
        c.pairs
            .iter()
            .filter(|p| p.kind == kind)
            .map(|p| (ms(p.gap), ms(p.period)))
            .filter(|(x, y)| {
                let px = (x / x_max * f64::from(w / CELL)) as u32;
                let py = (y / y_max * f64::from(h / CELL)) as u32;
                seen.insert((px, py))
            })
            .collect()
    };
    let blue = BLUE.mix(0.5);
    chart
        .draw_series(
            points(Kind::Accepted)
                .into_iter()
                .map(|xy| Circle::new(xy, 3, blue.filled())),
        )?
        .label(format!(
            "{} legal pairs, accepted (max gap {} ms, max period {} ms)",
            count(Kind::Accepted),
            ms(max(Kind::Accepted, |p| p.gap)),
            ms(max(Kind::Accepted, |p| p.period))
        ))
        .legend(move |(x, y)| Circle::new((x + 8, y), 3, blue.filled()));
    let orange = RGBColor(230, 120, 0);
    chart
        .draw_series(
            points(Kind::SrvtReported)
                .into_iter()
                .map(|xy| TriangleMarker::new(xy, 3, orange.filled())),
        )?
        .label(format!(
            "{} pairs with frame 2 after SRVT: SRVT timeout reported",
            count(Kind::SrvtReported)
        ))
        .legend(move |(x, y)| TriangleMarker::new((x + 8, y), 4, orange.filled()));
    let green = RGBColor(0, 140, 60);
    chart
        .draw_series(points(Kind::SctReported).into_iter().map(|(x, y)| {
            EmptyElement::at((x, y)) + Rectangle::new([(-2, -2), (2, 2)], green.filled())
        }))?
        .label(format!(
            "{} pairs with frame 1 after SCT: SCT timeout reported, pair accepted",
            count(Kind::SctReported)
        ))
        .legend(move |(x, y)| Rectangle::new([(x + 5, y - 3), (x + 11, y + 3)], green.filled()));
    let srvt_style = RED.stroke_width(2);
    chart
        .draw_series(LineSeries::new(
            [(ms(c.srvt), 0.0), (ms(c.srvt), y_max)],
            srvt_style,
        ))?
        .label(format!("SRVT {} ms", ms(c.srvt)))
        .legend(move |(x, y)| PathElement::new([(x, y), (x + 16, y)], srvt_style));
    let sct_style = RGBColor(150, 0, 150).stroke_width(2);
    chart
        .draw_series(LineSeries::new(
            [(0.0, ms(c.sct)), (x_max, ms(c.sct))],
            sct_style,
        ))?
        .label(format!("SCT {} ms", ms(c.sct)))
        .legend(move |(x, y)| PathElement::new([(x, y), (x + 16, y)], sct_style));
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerLeft)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 12))
        .draw()?;
    root.present()?;
    Ok(())
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [input, out] = args.as_slice() else {
        eprintln!("usage: srdo_plot PAIRS.csv OUT.svg");
        return ExitCode::from(2);
    };
    let campaign = match std::fs::read_to_string(input)
        .map_err(|e| e.to_string())
        .and_then(|t| parse(&t))
    {
        Ok(c) => c,
        Err(e) => {
            eprintln!("{input}: {e}");
            return ExitCode::from(2);
        }
    };
    if let Err(e) = draw(&campaign, out) {
        eprintln!("{out}: {e}");
        return ExitCode::FAILURE;
    }
    ExitCode::SUCCESS
}

#[cfg(test)]
mod tests {
    use super::*;

    const CSV: &str = "# seed 0x1, 3 producer cycles, ticks of 100 us, srvt_ticks 200, sct_ticks 500\n\
                       gap_ticks,period_ticks,reported\n\
                       12,480,\n\
                       201,300,srvt\n\
                       0,501,sct\n";

    #[test]
    fn the_limits_and_every_pair_are_read() {
        let c = parse(CSV).unwrap();
        assert_eq!((c.srvt, c.sct), (200, 500));
        let got: Vec<_> = c.pairs.iter().map(|p| (p.gap, p.period, p.kind)).collect();
        assert!(
            got == [
                (12, 480, Kind::Accepted),
                (201, 300, Kind::SrvtReported),
                (0, 501, Kind::SctReported)
            ]
        );
    }

    #[test]
    fn a_bad_line_is_refused() {
        assert!(parse(&CSV.replace("201,300,srvt", "201,,srvt")).is_err());
        assert!(parse(&CSV.replace("srvt\n", "late\n")).is_err());
        assert!(parse(&CSV.replace("srvt_ticks 200", "srvt_ticks x")).is_err());
    }

    #[test]
    fn the_plot_names_the_limits() {
        let out = std::env::temp_dir().join(format!("srdo_plot_{}.svg", std::process::id()));
        draw(&parse(CSV).unwrap(), out.to_str().unwrap()).unwrap();
        let svg = std::fs::read_to_string(&out).unwrap();
        let _ = std::fs::remove_file(&out);
        assert!(svg.contains("SRVT 20 ms") && svg.contains("SCT 50 ms"));
        assert!(svg.contains("1 legal pairs, accepted (max gap 1.2 ms, max period 48 ms)"));
    }
}
