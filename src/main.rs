//! The `jamchart` binary: all the work is in the library's `cli` module.

fn main() {
    std::process::exit(jamchart::cli::main());
}
