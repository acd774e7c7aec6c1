//! Loads every model file given on the command line and says which load and which define KANE().

fn main() {
    for path in std::env::args().skip(1) {
        let src = std::fs::read_to_string(&path).unwrap();
        match kane_model::lang::load(&path, &src) {
            Ok(m) => println!("OK   {path}: kane={}", m.equations.is_some()),
            Err(r) => print!("FAIL {path}\n{r}"),
        }
    }
}
