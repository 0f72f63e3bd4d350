use tiltpad::bearing::solve_case;
use tiltpad::model::load_case;
fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let text = std::fs::read_to_string(&args[0]).unwrap();
    let set: Vec<String> = args[1..].to_vec();
    let (_, case) = load_case(&text, &set).unwrap();
    let mut t = vec![];
    for _ in 0..15 {
        let t0 = web_time::Instant::now();
        let s = solve_case(&case).unwrap();
        t.push(t0.elapsed().as_secs_f64() * 1e3);
        std::hint::black_box(s);
    }
    t.sort_by(f64::total_cmp);
    println!("median {:.2} ms  min {:.2} ms", t[t.len() / 2], t[0]);
}
