//! The Hertz contact of a steel ball on a flat steel plate, and of the report's
//! high-speed twin-disc pair (Table 2-1, HS k = 5), from radii and load.
use traction_hertz::{Body, Geometry, HertzError};

fn main() -> Result<(), HertzError> {
    // Radii in m along the rolling direction x and across it; flat = infinity.
    let ball = Body::new(0.01, 0.01, 210e9, 0.3);
    let plate = Body::new(f64::INFINITY, f64::INFINITY, 210e9, 0.3);
    let c = Geometry::new(&ball, &plate)?.at_load(100.0)?;
    println!(
        "ball on flat, 100 N: a = {:.4} mm, b = {:.4} mm, P0 = {:.3} GPa",
        c.a * 1e3,
        c.b * 1e3,
        c.p0 / 1e9
    );
    // Closed form of the sphere on a flat: a = (3FR/(4E*))^(1/3), E* = E/(2(1−ν²)).
    let e_star: f64 = 210e9 / (2.0 * (1.0 - 0.3 * 0.3));
    let a = (3.0 * 100.0 * 0.01 / (4.0 * e_star)).cbrt();
    assert!((c.a / a - 1.0).abs() < 1e-12 && (c.b / c.a - 1.0).abs() < 1e-12);

    // A toroid (Rx 33 mm, Ry 270 mm) on a cylinder (Rx 71.4 mm): an elliptical
    // contact, long across the rolling direction.
    let toroid = Body::steel(33e-3, 270e-3);
    let disc = Body::steel(71.4e-3, f64::INFINITY);
    let g = Geometry::new(&toroid, &disc)?;
    let c = g.at_load(1500.0)?;
    println!(
        "toroid on disc, 1500 N: k = b/a = {:.3}, a = {:.3} mm, b = {:.3} mm, P0 = {:.3} GPa",
        g.k,
        c.a * 1e3,
        c.b * 1e3,
        c.p0 / 1e9
    );
    // The report prints P0 = 1.0 GPa for this load (Table 2-3, test 790126-03).
    assert!((c.p0 / 1e9 - 1.0).abs() < 0.05);
    // The load for a given pressure is the inverse.
    let back = g.at_p0(c.p0)?;
    assert!((back.load / 1500.0 - 1.0).abs() < 1e-12);
    Ok(())
}
