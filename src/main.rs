//! tiltpad entry point: the CLI (`tiltpad solve`, `tiltpad sweep`).

use clap::Parser;

fn main() {
    let cli = tiltpad::cli::Cli::parse();
    let Some(command) = cli.command else {
        eprintln!("usage: tiltpad solve CASE [--set key=value]... [--json OUT]\n       tiltpad sweep CASE --param KEY --from A --to B --steps N --csv OUT");
        std::process::exit(2);
    };
    if let Err(e) = tiltpad::cli::run(command) {
        eprintln!("error: {e:#}");
        std::process::exit(1);
    }
}
