//! Standard output for the `kane` command: a closed pipe (`kane eoms FILE | head`) ends the
//! program quietly, as command-line tools do, instead of a panic; any other write error ends it
//! with a message.

use std::io::{self, Write};

/// Writes `text` to standard output.
pub fn write(text: std::fmt::Arguments<'_>) {
    let mut out = io::stdout().lock();
    if let Err(e) = out.write_fmt(text).and_then(|()| out.flush()) {
        closed(&e);
    }
}

fn closed(e: &io::Error) -> ! {
    if e.kind() == io::ErrorKind::BrokenPipe {
        std::process::exit(0);
    }
    eprintln!("kane: cannot write the output: {e}");
    std::process::exit(1);
}

/// `print!` through [`write()`].
macro_rules! out {
    ($($arg:tt)*) => { $crate::output::write(format_args!($($arg)*)) };
}

/// `println!` through [`write()`].
macro_rules! outln {
    () => { $crate::output::write(format_args!("\n")) };
    ($($arg:tt)*) => { $crate::output::write(format_args!("{}\n", format_args!($($arg)*))) };
}

pub(crate) use {out, outln};
