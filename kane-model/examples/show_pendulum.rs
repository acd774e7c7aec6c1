fn main() {
    let mut g = kane_model::models::GimbalGyroscope::new().unwrap();
    let e = g.model.kane().unwrap();
    for f in &e.forcing {
        println!("f = {}\n", g.model.ar.to_text(*f));
    }
    for r in &e.mass_matrix {
        for x in r {
            println!("M = {}", g.model.ar.to_text(*x));
        }
    }
}
