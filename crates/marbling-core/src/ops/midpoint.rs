//! The implicit midpoint rule's Newton step, shared by the ops that solve it (stylus,
//! flow): M = q + h·u(M) for the midpoint M of a sub-step.

/// The Newton update d of M for M − q − h·u(M) = 0, given u and its Jacobian
/// j = [∂uₓ/∂x, ∂uₓ/∂y, ∂u_y/∂x, ∂u_y/∂y] at M: the solution of (I − h·j)·d = M − q − h·u
/// (subtract it from M).
#[inline(always)]
pub(crate) fn newton_update(
    m: [f64; 2],
    q: [f64; 2],
    h: f64,
    u: [f64; 2],
    j: [f64; 4],
) -> [f64; 2] {
    let (fx, fy) = (m[0] - q[0] - h * u[0], m[1] - q[1] - h * u[1]);
    let (a, b, c, d) = (1.0 - h * j[0], -h * j[1], -h * j[2], 1.0 - h * j[3]);
    let det = a * d - b * c;
    [(d * fx - b * fy) / det, (a * fy - c * fx) / det]
}
