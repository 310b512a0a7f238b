//! `cargo openr view PATH`: replays a recording (`cargo openr run MS --record DIR`) or
//! a `--trace` file in the live view's page, with a timeline (seek, play, step).
use std::path::PathBuf;

use crate::shell::Shell;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// A directory written by `run --record`, or a trace file written by `run --trace`
    #[arg(value_name = "DIR|TRACE")]
    path: PathBuf,
    /// Serve the page on ADDR (default 127.0.0.1:0: a free loopback port; printed as `Viewing http://ADDR/`)
    #[arg(long, value_name = "ADDR", default_value = "127.0.0.1:0")]
    addr: std::net::SocketAddr,
}

pub fn exec(args: Args, shell: &mut Shell) -> anyhow::Result<()> {
    let rec = openr_view::replay::open(&args.path).map_err(anyhow::Error::msg)?;
    let robots: Vec<String> = rec
        .robots
        .iter()
        .map(|r| {
            let end = r.moments.len().checked_sub(1).and_then(|i| r.moments.t_ms(i)).unwrap_or(0);
            format!("{} moments to {end} ms, {} camera pictures{}", r.moments.len(), r.pictures.len(), if r.speaker.is_some() { ", sound" } else { "" })
        })
        .collect();
    let what = match &rec.world {
        None => format!("{} ({})", args.path.display(), robots[0]),
        Some(w) => {
            let each: Vec<String> = robots.iter().enumerate().map(|(k, r)| format!("robot {k}: {r}")).collect();
            format!("{} (a world of {} robots, {} ground-truth frames; {})", args.path.display(), robots.len(), w.truth.len(), each.join("; "))
        }
    };
    let view = openr_view::View::bind(args.addr).map_err(|e| anyhow::anyhow!(e.replacen("--view", "--addr", 1)))?;
    view.replay(rec).map_err(anyhow::Error::msg)?;
    shell.status("Replaying", &what);
    eprintln!("Viewing http://{}/", view.addr());
    // The server's threads answer until the user stops the command (Ctrl-C).
    loop {
        std::thread::park();
    }
}
