//! A curvature-continuous UAV path through five waypoints (paper 003): Dubins-style local
//! curves (lines and arcs of radius 80) blended by the BFBS with i = 2 (C²), sampled with
//! its curvature, and its length.
//!
//! Run with `cargo run --release --example gerbs_path`.

use trajverify::algo::gerbs::{bfbs::Bfbs, path::GerbsPath, path::PathSpec, GerbsError};
use trajverify::curve::parametric::{curvature, ParamCurve, ParamCurveArclen};

fn main() -> Result<(), GerbsError> {
    let waypoints = vec![
        [0.0, 0.0],
        [300.0, 100.0],
        [600.0, -50.0],
        [900.0, 150.0],
        [1200.0, 0.0],
    ];
    // The paper's defaults: θ_o = π/8, arcs in the turn direction, lines at both ends.
    let spec = PathSpec::new(waypoints.clone(), 80.0, &());
    let path = GerbsPath::new(&spec, Bfbs::uniform(2, waypoints.len())?)?;
    let (t0, t1) = path.domain();
    println!(
        "GERBS path on t ∈ [{t0}, {t1}], length {:.6} m",
        path.length().expect("the whole path")
    );
    println!("   t       x          y        |κ| (1/m)");
    for i in 0..=8 {
        let t = i as f64 / 8.0;
        let [x, y] = path.point(&t).expect("t lies in [0, 1]");
        let kappa = curvature(&path, &t).expect("t lies in [0, 1]");
        println!("  {t:.3}  {x:9.3}  {y:9.3}  {kappa:.6}");
    }
    match path.point(&1.5) {
        Err(e) => println!("outside the domain: {e}"),
        Ok(p) => println!("unexpected point {p:?}"),
    }
    Ok(())
}
