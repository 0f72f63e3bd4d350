//! The keys of a controller description — the `[control]` section of a rotor file — one table like the rotor
//! file's ([`super::rotor_schema`], rows of `KeySpec<RotorFile>`): dotted key, unit, allowed values, typical
//! range, typed default and meaning. `tiltpad schema --rotor` prints it after the rotor keys, and
//! [`super::control`] reads every range, default and unit from it (through [`control_row`]).

use super::error::Range;
use super::rotor::RotorFile;
use super::schema::{Fallback, KeySpec};
use crate::units::{COUNT, HZ_ANGULAR, N_PER_V, ONE, RPM, VOLT, V_PER_MM_S, V_PER_UM};

type Key = KeySpec<RotorFile>;

/// Gains: any sign (a negative gain is a sign flip), finite.
const GAIN: Range = Range::closed(-1e6, 1e6);

/// Every controller key, in file order.
pub const CONTROL_KEYS: &[Key] = &[
    Key::number("control.gain", ONE, GAIN)
        .typical(0.0, 2.0)
        .or(1.0)
        .meaning("Multiplies every controller (u = −gain · K(s) y): 0 opens the loop, −1 flips its sign. The gain sweep and the Control view's slider vary it."),
    Key::rule("control.sensor[].node", COUNT, "integer in [0, last node]")
        .default(Fallback::Rule("— (or bearing)"))
        .meaning("Rotor node the sensor measures (a probe anywhere on the shaft)."),
    Key::rule("control.sensor[].bearing", COUNT, "integer in [0, bearings − 1]")
        .default(Fallback::Rule("— (or node)"))
        .meaning("The sensor measures the journal of rotor.bearing[i]."),
    Key::choice("control.sensor[].direction", &["x", "y"])
        .meaning("Measured direction: x horizontal, y vertical (the bearing's frame)."),
    Key::choice("control.sensor[].quantity", &["displacement", "velocity"])
        .default(Fallback::Word("displacement"))
        .meaning("A proximity probe (displacement, read in µm by the gains) or a velocity pickup (read in mm/s)."),
    Key::choice("control.actuator[].kind", &["valve", "force"])
        .default(Fallback::Word("valve"))
        .meaning("The servovalve of a controllable bearing (valve → lines → nozzles → film), or an ideal force actuator (flat or second order: closed-form checks, what-if studies)."),
    Key::rule("control.actuator[].bearing", COUNT, "integer in [0, bearings − 1]; its case has [hydraulics]")
        .default(Fallback::Rule("— (valve)"))
        .meaning("The bearing position whose case's valve ([hydraulics]) this actuator drives."),
    Key::rule("control.actuator[].node", COUNT, "integer in [0, last node]")
        .default(Fallback::Rule("— (force)"))
        .meaning("Node a force actuator pushes."),
    Key::choice("control.actuator[].direction", &["x", "y"])
        .default(Fallback::Rule("— (force)"))
        .meaning("Direction a force actuator pushes."),
    Key::number("control.actuator[].gain_n_per_v", N_PER_V, GAIN)
        .typical(10.0, 1000.0)
        .default(Fallback::Rule("— (force)"))
        .meaning("Static force per volt of a force actuator."),
    Key::number("control.actuator[].natural_frequency_hz", HZ_ANGULAR, Range::positive(1e6))
        .typical(50.0, 2000.0)
        .default(Fallback::Rule("flat (no dynamics)"))
        .meaning("A force actuator with second-order dynamics: its natural frequency."),
    Key::number("control.actuator[].damping_ratio", ONE, Range::positive(10.0))
        .typical(0.3, 1.0)
        .or(0.7)
        .meaning("A second-order force actuator's damping ratio."),
    Key::number("control.actuator[].max_voltage_v", VOLT, Range::positive(1e3))
        .typical(0.1, 10.0)
        .default(Fallback::Rule("the valve's small-signal range (10 % of full scale); 10 V for a force actuator"))
        .meaning("Control amplitude above which the actuator saturates (the linear model no longer holds): responses that need more are marked."),
    Key::rule("control.loop[].actuator", COUNT, "integer in [0, actuators − 1]; one loop per actuator")
        .meaning("The actuator this loop drives."),
    Key::rule("control.loop[].sensor", COUNT, "integer in [0, sensors − 1]").meaning("The sensor this loop reads."),
    Key::choice("control.loop[].law", &["pd", "transfer_function"])
        .default(Fallback::Word("pd"))
        .meaning("Proportional–derivative with a first-order roll-off, K(s) = kp + kd s/(1 + s/ω_f), or a general transfer function."),
    Key::number("control.loop[].kp_v_per_um", V_PER_UM, GAIN)
        .typical(-0.1, 0.1)
        .or(0.0)
        .meaning("Proportional gain on a displacement sensor: volts per µm (u = −kp y; positive opposes a positive reading when the valve pushes that way)."),
    Key::number("control.loop[].kd_v_per_mm_s", V_PER_MM_S, GAIN)
        .typical(-1.0, 1.0)
        .or(0.0)
        .meaning("Derivative gain: volts per mm/s of the sensor's velocity (a displacement differentiated through the roll-off, or a velocity pickup's signal)."),
    Key::number("control.loop[].rolloff_hz", HZ_ANGULAR, Range::positive(1e6))
        .typical(100.0, 2000.0)
        .default(Fallback::Rule("none (required with kd on a displacement sensor)"))
        .meaning("First-order roll-off of the derivative term (a low-pass on a velocity pickup)."),
    Key::rule("control.loop[].numerator", ONE, "finite coefficients, highest power of s first (s in rad/s); degree ≤ the denominator's")
        .default(Fallback::Rule("— (transfer_function)"))
        .meaning("Numerator of K(s) from the sensor signal (µm, or mm/s for a velocity pickup) to volts."),
    Key::rule("control.loop[].denominator", ONE, "finite coefficients, highest power first; every root with Re < 0")
        .default(Fallback::Rule("— (transfer_function)"))
        .meaning("Denominator of K(s); a controller unstable on its own is refused."),
    Key::rule("control.mimo.kp_v_per_um", V_PER_UM, "a row per actuator, a column per sensor; finite, 0 on velocity sensors")
        .default(Fallback::Rule("zeros"))
        .meaning("Proportional gain matrix (u = −(Kp y + Kd ẏ_f))."),
    Key::rule("control.mimo.kd_v_per_mm_s", V_PER_MM_S, "a row per actuator, a column per sensor; finite")
        .default(Fallback::Rule("zeros"))
        .meaning("Derivative gain matrix, each entry through the roll-off."),
    Key::number("control.mimo.rolloff_hz", HZ_ANGULAR, Range::positive(1e6))
        .typical(100.0, 2000.0)
        .default(Fallback::Rule("none (required with kd on a displacement sensor)"))
        .meaning("First-order roll-off of every derivative term."),
    Key::number("control.lqr.design_speed_rpm", RPM, Range::positive(1e6))
        .typical(1000.0, 20000.0)
        .default(Fallback::Rule("required on a rotor; the case's speed on the test rig"))
        .meaning("Spin speed of the plant the LQR is designed on (its reduced model); the same controller then runs at every speed of the sweep."),
    Key::number("control.lqr.output_weight", ONE, Range::closed(0.0, 1e12))
        .typical(0.01, 100.0)
        .or(1.0)
        .meaning("Weight q of each sensor's reading squared in the cost ∫ Σ q y² + Σ r u² dt (y in µm, mm/s for a velocity pickup): one per sensor."),
    Key::number("control.lqr.input_weight", ONE, Range::open_lo(0.0, 1e12))
        .typical(0.01, 100.0)
        .or(1.0)
        .meaning("Weight r of each actuator's signal squared (u in volts): one per actuator; larger asks less of the valve."),
    Key::number("control.lqr.max_frequency_hz", HZ_ANGULAR, Range::positive(1e6))
        .typical(100.0, 1000.0)
        .or(300.0)
        .meaning("The reduced model keeps the plant's modes below this frequency (and every unstable one); the valve's and the lines' faster modes are left out of the design, not out of the closed loop."),
    Key::number("control.lqr.sensor_noise", ONE, Range::open_lo(0.0, 1e12))
        .typical(1e-4, 1.0)
        .or(0.01)
        .meaning("The observer (Kalman filter): sensor-noise intensity per unit disturbance at the actuator inputs (reading units² per V²); smaller trusts the sensors more (a faster observer)."),
];

/// The row of a controller key (its row key, `[]` for array entries), found while compiling:
/// `const { control_row("control.gain") }`; a key without a row fails the build.
#[must_use]
pub const fn control_row(key: &str) -> &'static Key {
    let mut i = 0;
    while i < CONTROL_KEYS.len() {
        if super::schema::same_text(CONTROL_KEYS[i].key, key) {
            return &CONTROL_KEYS[i];
        }
        i += 1;
    }
    panic!("no row in model::control_schema::CONTROL_KEYS for this key")
}
