//! The `jamchart` binary: all the work is in the library's command line (`jamchart::run_cli`).

fn main() {
    std::process::exit(jamchart::run_cli());
}
