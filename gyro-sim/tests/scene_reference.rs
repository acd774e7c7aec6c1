use gyro_sim::{resolve, Registry, Scene};

const HEAD: &str = "model = \"heavy_top\"\nt_final = 1.0\noutput_step = 0.1\n";
const AXLE: &str = "[axle]\ntilt = \"30 deg\"\nquaternion = [\"E4\", \"E1\", \"E2\", \"E3\"]\n";

#[test]
fn probe() {
    let cases = [
        format!("{HEAD}[view]\nup = 5\n"),
        format!("{HEAD}[view]\nup = -3\n"),
        format!("{HEAD}[view]\ndraw_model = true\n"),
        format!("{HEAD}[specified]\nT = \"1\"\n"),
        format!("{HEAD}{AXLE}[[events]]\npreset = \"gimbal_lock\"\nangle = \"E1\"\nmargin = 95\n"),
        format!("{HEAD}{AXLE}[[events]]\npreset = \"gimbal_lock\"\nangle = \"E1\"\nmargin = 1.5\n"),
        format!("{HEAD}{AXLE}[[events]]\npreset = \"gimbal_lock\"\nangle = \"E1\"\nmargin = \"5 degrees\"\n"),
        format!("{HEAD}[axle]\ntilt = 5\nquaternion = [\"E4\", \"E1\", \"E2\", \"E3\"]\n"),
        format!("{HEAD}[axle]\ntilt = \"30 degrees\"\nquaternion = [\"E4\", \"E1\", \"E2\", \"E3\"]\n"),
        format!("{HEAD}[parameters]\nD = \"30 cm\"\nRR = \"2 ft\"\n"),
        format!("{HEAD}[integrator]\nmethod = \"rk4\"\n[[events]]\nwhen = \"t - 0.5\"\n"),
        format!("{HEAD}[integrator]\nmethod = \"dop853\"\nstep = -1\n"),
        format!("{HEAD}[integrator]\nmethod = \"taylor\"\naccuracy = 1e-6\n"),
        format!("{HEAD}plot_points = 10\n[integrator]\nmethod = \"rk4\"\n"),
        format!("{HEAD}{AXLE}[[controls]]\nname = \"tilt\"\nmin = 0\nmax = 90\nunit = \"DEG\"\n"),
        format!("{HEAD}{AXLE}[[controls]]\nname = \"tilt\"\nmin = 0\nmax = 90\nunit = \"rad\"\n"),
        format!("{HEAD}[parameters]\nM = 2\n[[controls]]\nname = \"m\"\nmin = 0\nmax = 90\n"),
        format!("{HEAD}[parameters]\nM = 2\nm = 3\n"),
        format!("{HEAD}[[events]]\nwhen = \"W3 - 1\"\ncount = 2\n[[events]]\nname = \"EVENT1\"\nwhen = \"W3\"\n"),
        format!("{HEAD}[[view.bodies]]\nname = \"a\"\ncolour = \"#00ff00\"\nshape = {{ kind = \"axes\" }}\nopacity = 2\n"),
        format!("{HEAD}[[view.bodies]]\nname = \"a\"\ncolour = \"#00ff00\"\nshape = {{ kind = \"rod\", length = \"2*Q\" }}\n"),
        format!("{HEAD}[[view.bodies]]\nname = \"a\"\ncolour = \"#00ff00\"\nshape = {{ kind = \"rod\", length = \"-2*D\" }}\n"),
        format!("{HEAD}outputs = [\"e1\", \"axle\", \"elevation\"]\n"),
        format!("model = \"gimbal_gyroscope\"\nt_final = 1\noutput_step = 1\n[initial]\nQ2 = 30\n"),
        format!("{HEAD}[parameters]\nM = true\n"),
        format!("{HEAD}title = 3\n"),
        format!("{HEAD}[[view.points]]\nname = \"p\"\nposition = [\"AXLE_N1\", \"AXLE_N2\", \"axle_n3\"]\ncolour = \"#000000\"\nfrom = \"q\"\n"),
    ];
    let registry = Registry::builtin();
    for c in cases {
        println!("---- {c:?}");
        match Scene::parse("s.toml", &c) {
            Ok(s) => match resolve(&s, &registry) {
                Ok(p) => println!(
                    "RESOLVED init {:?} params {:?} method {:?} picks {}",
                    p.initial,
                    p.params,
                    s.integrator.method.name(),
                    p.picks.len()
                ),
                Err(e) => println!("RESOLVE ERR {e}"),
            },
            Err(e) => println!("PARSE ERR {e}"),
        }
    }
}
