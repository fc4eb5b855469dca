"""One regularised simulation to the jam by scipy's Radau IIA: the baseline `cargo bench --bench
scipy` times beside one jamchart RADAU5 run.

The same ODE as src/dynamics/system.rs with the motion drive: state y = (theta, x, v) in rad, mm,
mm/s; the palm turns at theta_dot = -omega; Adams' IMPACT force on the penetration delta with its
damping ramp, and his STEP-regularised Coulomb friction at the palm (on the slip u_B measured at
the palm's face) and at the ground (src/dynamics/contact.rs). Parameters: the default scene and
`[dynamics]` of config/paper.toml. The right-hand side works on three Python floats with `math`
(numpy's per-call overhead on a 3-vector costs more than the arithmetic), and scipy gets the
analytic Jacobian (otherwise its Radau differences it, three more calls per Jacobian).

The jam is read as jamchart reads it (src/dynamics/jam.rs), by terminal events located on the
dense output: the detector arms at the first step end with v at 0.9 v_geo(theta) or above; a
candidate is the first later instant with v below 0.5 v_geo (x_jam is its x); it is confirmed
when the disc has not recovered to 0.9 v_geo during the window max(0.25 deg of palm turn, two
periods of the disc on the contact), restarted when the palm loses the disc and then at least
1.5 times a bounce's flight 2 v_geo / (mu_g g); a recovered candidate is discarded and the
search goes on. A contact past the palm's end before the jam ends the run (beyond reach). Same
tolerances: rtol = atol (jamchart's default 1e-6), largest step 1 deg of palm turn (jamchart's).

Usage:
  python radau.py check JAMCHART   x_jam of jamchart (the binary) and of scipy on two stiff
                                   cases, how far apart, and exit 1 when they disagree
  python radau.py serve            one integration of the defaults per line of stdin, at the
                                   rtol (= atol) the line holds; prints
                                   `wall_s <s> cpu_s <s> x_jam_mm <mm> steps <n>` (the
                                   integration alone: the process start and imports are no
                                   part of a run)
  python radau.py runs N RTOL      N integrations at RTOL, printed alike (for callgrind)
"""

import json
import math
import subprocess
import sys
import time

import numpy as np
import scipy
from scipy.integrate import solve_ivp

MM_PER_M = 1000.0


class Model:
    """The system of src/dynamics/system.rs, motion drive."""

    def __init__(self, stiffness=1e5, exponent=2.2, rtol=1e-6, atol=None):
        # Scene (config/paper.toml [scene]).
        self.r, self.h, self.m = 10.0, 0.0, 1.0
        self.weight = self.m * 9.806
        self.mu_ground = self.mu_palm = 0.4
        self.palm_length = 150.0
        self.theta0 = math.radians(90.0)
        # [dynamics]: drive, contact, friction, jam reading, integrator.
        self.omega = math.radians(30.0)
        self.k, self.e, self.c_max, self.depth = stiffness, exponent, 10.0, 0.01
        self.v_s, self.v_d = 0.1, 0.2
        self.jam_ratio, self.arm_ratio = 0.5, 0.9
        self.confirm_deg, self.bounce_factor = 0.25, 1.5
        self.rtol, self.atol = rtol, atol if atol is not None else rtol
        self.max_step = math.radians(1.0) / self.omega
        self.ground_decel = self.mu_ground * 9.806 * MM_PER_M

    # The contact laws (src/dynamics/contact.rs).

    @staticmethod
    def step(x, x0, h0, x1, h1):
        """Adams' STEP and its slope."""
        if x <= x0:
            return h0, 0.0
        if x >= x1:
            return h1, 0.0
        w = x1 - x0
        s = (x - x0) / w
        a = h1 - h0
        return h0 + a * s * s * (3.0 - 2.0 * s), a * 6.0 * s * (1.0 - s) / w

    def friction(self, mu, v):
        """The signed regularised coefficient mu(v) and d mu / dv (mu_s = mu_d = mu)."""
        a = abs(v)
        if a <= self.v_s:
            return self.step(v, -self.v_s, -mu, self.v_s, mu)
        m, dm = self.step(a, self.v_s, mu, self.v_d, mu)
        return math.copysign(m, v), dm

    # The equations of motion (src/dynamics/system.rs).

    def v_geo(self, theta):
        s, c = math.sin(theta), math.cos(theta)
        return self.omega * (self.r + (self.r + self.h) * c) / (s * s)

    def penetration(self, y):
        return self.r + self.h + self.r * math.cos(y[0]) - y[1] * math.sin(y[0])

    def touching_x(self, theta):
        return (self.r * (1.0 + math.cos(theta)) + self.h) / math.sin(theta)

    def forces(self, y, jac):
        """(v_dot, d v_dot / d y or None)."""
        theta, x, v = y[0], y[1], y[2]
        s, c = math.sin(theta), math.cos(theta)
        r, h, td = self.r, self.h, -self.omega
        delta = r + h + r * c - x * s
        s_b = x * c + r * s
        rate = -(v * s + s_b * td)
        n = n_d = n_r = 0.0
        if delta > 0.0:
            p = self.k * delta ** (self.e - 1.0)
            damp, d_damp = self.step(delta, 0.0, 0.0, self.depth, self.c_max)
            n = p * delta + damp * rate
            if n > 0.0:
                n_d, n_r = self.e * p + d_damp * rate, damp
            else:
                n = 0.0
        u_b = v * c - td * h
        mu_b, dmu_b = self.friction(self.mu_palm, u_b)
        px_k = s - mu_b * c
        py_k = c + mu_b * s
        r_n = self.weight + n * py_k
        mu_a, dmu_a = self.friction(self.mu_ground, v)
        kk = MM_PER_M / self.m
        accel = kk * (n * px_k - mu_a * abs(r_n))
        if not jac:
            return accel, None
        # Gradients over (theta, x, v); theta_dot is constant (motion drive).
        g_n = (
            n_d * -s_b + n_r * -(td * (r * c - x * s) + v * c),
            n_d * -s + n_r * -(td * c),
            n_r * -s,
        )
        g_mub = (dmu_b * -v * s, 0.0, dmu_b * c)
        g_pxk = (c + mu_b * s - c * g_mub[0], 0.0, -c * g_mub[2])
        g_pyk = (-s + mu_b * c + s * g_mub[0], 0.0, s * g_mub[2])
        sign = math.copysign(1.0, r_n)
        g = [
            px_k * g_n[i] + n * g_pxk[i] - mu_a * sign * (py_k * g_n[i] + n * g_pyk[i])
            for i in range(3)
        ]
        g[2] -= dmu_a * abs(r_n)
        return accel, [kk * gi for gi in g]

    def rhs(self, t, y):
        return [-self.omega, y[2], self.forces(y, False)[0]]

    def jacobian(self, t, y):
        _, g = self.forces(y, True)
        return np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], g])

    # The jam reading (src/dynamics/jam.rs).

    def period_s(self, delta):
        """Period of the disc oscillating on the contact's elastic slope at `delta` (mm)."""
        if delta <= 0.0:
            return 0.0
        slope = self.e * self.k * delta ** (self.e - 1.0)
        return 2.0 * math.pi * math.sqrt(self.m / (MM_PER_M * slope))

    def simulate(self):
        """x_jam in mm (None: beyond reach or never jams) and the accepted steps."""
        steps = 0
        t_end = self.theta0 / self.omega

        def event(fun, direction):
            fun.terminal, fun.direction = True, direction
            return fun

        recovered = event(lambda t, y: y[2] - self.arm_ratio * self.v_geo(y[0]), 1.0)
        beyond = event(lambda t, y: self.palm_length - (y[1] * math.cos(y[0])
                                                       + self.r * math.sin(y[0])), -1.0)
        lost = event(lambda t, y: self.penetration(y), -1.0)
        caught = event(lambda t, y: self.penetration(y), 1.0)
        armed = False

        def slowed(t, y):
            # Armed at the first step end (scipy evaluates the events there) with v at 0.9
            # v_geo, as jamchart's detector arms; until then no root. One call of solve_ivp
            # thus runs from the start to the candidate: a terminal arming event and a second
            # call from there took 4 more steps, 66 more right-hand sides (3 %) and 10 more
            # LU factorisations at the defaults.
            nonlocal armed
            v_geo = self.v_geo(y[0])
            armed = armed or y[2] >= self.arm_ratio * v_geo
            return y[2] - self.jam_ratio * v_geo if armed else 1.0

        slowed = event(slowed, -1.0)

        def run(t0, y0, t1, events):
            nonlocal steps
            sol = solve_ivp(self.rhs, (t0, t1), y0, method="Radau", rtol=self.rtol,
                            atol=self.atol, jac=self.jacobian, max_step=self.max_step,
                            events=events)
            steps += sol.t.size - 1
            for i, (te, ye) in enumerate(zip(sol.t_events, sol.y_events)):
                if te.size:
                    return i, te[0], ye[0]
            return None, sol.t[-1], sol.y[:, -1]

        t, y = 0.0, [self.theta0, self.touching_x(self.theta0), 0.0]
        while True:
            which, t, y = run(t, y, t_end, [slowed, beyond])
            if which != 0:
                return None, steps
            x_jam = y[1]
            window = max(math.radians(self.confirm_deg) / self.omega,
                         2.0 * self.period_s(self.penetration(y)))
            bounced = self.penetration(y) <= 0.0
            flight = 2.0 * self.v_geo(y[0]) / self.ground_decel
            # Confirmation: the window runs while the palm touches the disc; a recovery
            # (event 0) discards the candidate. Reaching the end of the push confirms it.
            while True:
                if bounced:
                    which, t, y = run(t, y, t_end, [recovered, caught])
                    if which != 1:
                        break
                    window = max(window, self.bounce_factor * flight)
                which, t, y = run(t, y, min(t + window, t_end), [recovered, lost])
                if which != 1:
                    break
                bounced = True
            if which is None:
                return x_jam, steps


def jamchart_x_jam(jamchart, args):
    out = subprocess.run(
        [jamchart, "solve", "--model", "dynamics", "--method", "radau5", "--no-verify",
         "--format", "json", *args],
        check=True, capture_output=True, text=True).stdout
    result = json.loads(out)["results"][0]
    return result["x_jam_mm"], result["steps"]


def model(args, rtol):
    keys = {"--stiffness": "stiffness", "--exponent": "exponent"}
    return Model(rtol=rtol, **{keys[k]: float(v) for k, v in zip(args[::2], args[1::2])})


def error_test_rtol(rtol):
    """The rtol at which scipy's Radau runs the error test jamchart's RADAU5 runs at `rtol`:
    RADAU5 (Hairer's, and jamchart's) applies 0.1 rtol^(2/3) to its lower-order error estimate,
    scipy the user's rtol as given (atol alike, in proportion)."""
    return 0.1 * rtol ** (2.0 / 3.0)


# The stiff cases checked: the defaults (k = 1e5 N/mm^2.2, about 59 um at 200 N) and the
# exponent 1.5.
CASES = [[], ["--stiffness", "1e5", "--exponent", "1.5"]]
RTOL, TIGHT = 1e-6, 1e-10


def check(jamchart):
    """Prints x_jam of jamchart and scipy on each case and says whether they agree: at rtol
    1e-6 within 1e-6 x_jam (the tolerance's expected error), at 1e-10 within 1e-9 x_jam."""
    print(f"scipy {scipy.__version__}, numpy {np.__version__}")
    ok = True
    for case in CASES:
        ours, ours_steps = jamchart_x_jam(jamchart, case + ["--rtol", str(RTOL)])
        ref, _ = jamchart_x_jam(jamchart, case + ["--rtol", str(TIGHT)])
        runs = {rtol: model(case, rtol).simulate()
                for rtol in (RTOL, error_test_rtol(RTOL), TIGHT)}
        if ours is None or any(x is None for x, _ in runs.values()):
            print(f"{case}: x_jam jamchart {ours}, scipy {runs}")
            ok = False
            continue
        theirs, steps = runs[RTOL]
        matched, matched_steps = runs[error_test_rtol(RTOL)]
        tight = runs[TIGHT][0]
        ok &= abs(theirs - ours) <= RTOL * ref and abs(tight - ref) <= 1e-9 * ref
        print(f"{' '.join(case) or 'defaults'}: x_jam at rtol {RTOL:g}: jamchart {ours:.9f} mm "
              f"({ours_steps} steps), scipy {theirs:.9f} mm ({steps} steps), "
              f"{abs(theirs - ours) / ref:.1e} apart (bound {RTOL:g}); at {TIGHT:g}: "
              f"jamchart {ref:.9f}, scipy {tight:.9f}, {abs(tight - ref) / ref:.1e} apart "
              f"(bound 1e-9); error from jamchart at {TIGHT:g}: jamchart "
              f"{abs(ours - ref) / ref:.1e}, scipy {abs(theirs - ref) / ref:.1e}, scipy at rtol "
              f"{error_test_rtol(RTOL):.3g} {abs(matched - ref) / ref:.1e} ({matched_steps} steps)")
    return ok


def timed(m):
    w0, c0 = time.perf_counter(), time.process_time()
    x_jam, steps = m.simulate()
    wall, cpu = time.perf_counter() - w0, time.process_time() - c0
    print(f"wall_s {wall:.6e} cpu_s {cpu:.6e} x_jam_mm {float(x_jam)!r} steps {steps}", flush=True)


def serve():
    """One integration of the defaults per line of stdin, at the rtol (= atol) the line holds."""
    models = {}
    for line in sys.stdin:
        rtol = float(line)
        timed(models.setdefault(rtol, model([], rtol)))


if __name__ == "__main__":
    if sys.argv[1] == "check":
        sys.exit(0 if check(sys.argv[2]) else 1)
    elif sys.argv[1] == "runs":
        m = model([], float(sys.argv[3]))
        for _ in range(int(sys.argv[2])):
            timed(m)
    else:
        serve()
