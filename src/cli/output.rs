//! The JSON output of `run`: a tree of numbers rendered as strings.
//!
//! An algorithm builds an [`Out<T>`] in whatever number type it ran in. Rendering is the only
//! place the number type matters: exact fractions for rationals, shortest round-trip decimals
//! for f64, for `mpfr:<bits>` the digits a ball computation at `<bits>` proves
//! ([`render_digits`]), and for `ball:<bits>` the enclosures ([`render_proven`]).

use super::input::RunError;
use crate::scalar::ball::Ball;
use crate::scalar::certify::format_float_digits;
use crate::scalar::{Field, Float, Real};
use serde_json::{Map, Value};

/// A JSON-like tree whose numbers are values of `T`.
#[derive(Clone, Debug)]
pub enum Out<T> {
    Num(T),
    /// A number that may vanish mathematically, with the scale of the quantities it was
    /// computed from. Printed like [`Out::Num`], except that a ball around 0 prints as the zero
    /// it proves, "0eK" ([`proven_text`]: a straight line's conversion error, an ERBS weight
    /// far below the resolution), not as a refusal.
    MaybeZero(T, T),
    List(Vec<Out<T>>),
    Object(Vec<(String, Out<T>)>),
    /// A count or an index: printed as a JSON integer, not a string.
    Int(i64),
    Text(String),
    /// A yes/no answer, printed as a JSON boolean.
    Bool(bool),
    /// A double reported as a JSON number (e.g. an f64 reference value), or null if not finite.
    F64(f64),
    /// A proven result known to lie in [lo, hi] (MPFR ends), whatever the tree's number type:
    /// printed by the proven renderers as a ball is, but without the f64 range of a ball's
    /// radius (κ₂ of 1e415 is proven by its ends).
    /// Boxed, so that the tree of an f64 run is not sized by two MPFR numbers per node.
    Bounds(Box<(Float, Float)>),
    Null,
}

impl<T> Out<T> {
    /// An object from (name, value) pairs, in order.
    pub fn object(fields: Vec<(&str, Out<T>)>) -> Self {
        Out::Object(
            fields
                .into_iter()
                .map(|(k, v)| (k.to_string(), v))
                .collect(),
        )
    }
    /// This object with one more field at the end (a non-object is returned unchanged).
    pub fn with_field(self, name: &str, value: Out<T>) -> Self {
        match self {
            Out::Object(mut fields) => {
                fields.push((name.to_string(), value));
                Out::Object(fields)
            }
            other => other,
        }
    }
    /// A list of numbers.
    pub fn nums(values: Vec<T>) -> Self {
        Out::List(values.into_iter().map(Out::Num).collect())
    }
    /// The same tree with every number mapped by `f` (a scale mapped alike).
    pub fn map<U>(&self, f: &impl Fn(&T) -> U) -> Out<U> {
        match self {
            Out::Num(x) => Out::Num(f(x)),
            Out::MaybeZero(x, s) => Out::MaybeZero(f(x), f(s)),
            Out::List(items) => Out::List(items.iter().map(|v| v.map(f)).collect()),
            Out::Object(fields) => {
                Out::Object(fields.iter().map(|(k, v)| (k.clone(), v.map(f))).collect())
            }
            Out::Int(i) => Out::Int(*i),
            Out::Text(s) => Out::Text(s.clone()),
            Out::Bool(b) => Out::Bool(*b),
            Out::F64(x) => Out::F64(*x),
            Out::Bounds(b) => Out::Bounds(b.clone()),
            Out::Null => Out::Null,
        }
    }
    /// Every number of the tree with its path, in order (a scale is not a number of the
    /// output).
    pub fn numbers<'a>(&'a self, path: &str, found: &mut Vec<(String, &'a T)>) {
        match self {
            Out::Num(x) | Out::MaybeZero(x, _) => found.push((path.to_string(), x)),
            Out::List(items) => {
                for (i, v) in items.iter().enumerate() {
                    v.numbers(&format!("{path}[{i}]"), found);
                }
            }
            Out::Object(fields) => {
                for (k, v) in fields {
                    v.numbers(&field_path(path, k), found);
                }
            }
            _ => {}
        }
    }
    /// About the length of the tree's compact JSON text, for reserving it at once: a
    /// megabyte of output grown by doubling is copied about twice and faults in fresh
    /// pages at every step.
    pub fn text_size_hint(&self) -> usize
    where
        T: Field,
    {
        match self {
            // A list of numbers is taken as its first number's length times its length: an
            // estimate costs nothing next to the printing of 10⁵ numbers it is made for.
            Out::List(items) => match items.first() {
                Some(first @ (Out::Num(_) | Out::MaybeZero(..))) => {
                    2 + items.len() * (1 + first.text_size_hint())
                }
                _ => 2 + items.iter().map(|v| 1 + v.text_size_hint()).sum::<usize>(),
            },
            Out::Object(fields) => {
                2 + fields
                    .iter()
                    .map(|(k, v)| k.len() + 4 + v.text_size_hint())
                    .sum::<usize>()
            }
            Out::Text(s) => s.len() + 2,
            Out::Num(x) | Out::MaybeZero(x, _) => x.plain_string_len_hint() + 2,
            _ => 24,
        }
    }
    /// The top-level fields of an object (the whole tree as one unnamed field otherwise).
    pub fn fields(&self) -> Vec<(String, &Out<T>)> {
        match self {
            Out::Object(fields) => fields.iter().map(|(k, v)| (k.clone(), v)).collect(),
            other => vec![(String::new(), other)],
        }
    }
}

/// The level below which a value computed at the working precision cannot be told from 0
/// next to quantities of size `scale`: 2^(16−p)·|scale| at p bits.
///
/// A quantity that vanishes mathematically comes out as rounding noise of either sign, on
/// which no two precisions agree, so printing it certified is impossible; below this level
/// it is printed as 0. Used only where the output has a natural scale (coordinates next to
/// the largest coordinate), never for values computed with relative accuracy.
pub fn noise_level<T: Real>(scale: &T) -> T {
    let ctx = scale.ctx();
    let bits = T::precision_bits(&ctx).saturating_sub(16);
    scale.clone().abs() * &crate::scalar::powi(&T::from_ratio(1, 2, &ctx), bits)
}

/// x, or 0 when |x| is below `level`, in f64 only: an f64 answer prints its mathematical
/// zeros as 0, not as rounding noise. Enclosures (which `mpfr:<bits>` prints too) keep their
/// balls around 0, the honest answer.
pub fn flush<T: Real>(x: T, level: Option<&T>) -> T {
    if T::ENCLOSURE || T::scalar_name(&x.ctx()) != "f64" {
        return x;
    }
    match level {
        Some(l) if x.clone().abs() < *l => T::zero_in(&x.ctx()),
        _ => x,
    }
}

/// The largest |x| of `values`, if there is one.
pub fn largest<'a, T: Real + 'a>(values: impl IntoIterator<Item = &'a T>) -> Option<T> {
    if T::ENCLOSURE {
        return None; // only used to scale the noise level, which enclosures do not flush
    }
    values.into_iter().fold(None, |m: Option<T>, x| {
        let a = x.clone().abs();
        match m {
            Some(m) if m >= a => Some(m),
            _ => Some(a),
        }
    })
}

fn f64_value(x: f64) -> Value {
    serde_json::Number::from_f64(x).map_or(Value::Null, |n| {
        // With arbitrary_precision a Number keeps text; give it the shortest round-trip form.
        serde_json::from_str(&crate::scalar::float_text(x)).unwrap_or(Value::Number(n))
    })
}

/// The path of field `key` inside the object at `path` ("a.b"), for error messages.
fn field_path(path: &str, key: &str) -> String {
    if path.is_empty() {
        key.to_string()
    } else {
        format!("{path}.{key}")
    }
}

/// Render with every number as its plain string (`to_plain_string`).
pub fn render_plain<T: Field>(out: &Out<T>) -> Value {
    match out {
        Out::Num(x) | Out::MaybeZero(x, _) => Value::String(x.to_plain_string()),
        Out::List(items) => Value::Array(items.iter().map(render_plain).collect()),
        Out::Object(fields) => Value::Object(
            fields
                .iter()
                .map(|(k, v)| (k.clone(), render_plain(v)))
                .collect::<Map<_, _>>(),
        ),
        Out::Int(i) => Value::from(*i),
        Out::Text(s) => Value::String(s.clone()),
        Out::Bool(b) => Value::Bool(*b),
        Out::F64(x) => f64_value(*x),
        Out::Bounds(b) => {
            let (lo, hi) = &**b;
            let mid = Float::with_val(lo.prec().max(hi.prec()) + 1, lo + hi) / 2u32;
            Value::String(mid.to_string())
        }
        Out::Null => Value::Null,
    }
}

/// The compact JSON text of [`render_plain`]`(out)`, written straight from the tree (no JSON
/// value and no string per number: an f64 run prints 10⁵ numbers in a few milliseconds).
///
/// Returns the top-level keys of an object (for the fields appended later), or `None`, with
/// `text` unspecified, where the text could differ from the value route's: an object that
/// repeats a key (a JSON map keeps one), a number that is not finite or a string that says
/// NaN or infinity (which [`check_finite`] refuses, naming its path). The caller then takes
/// the value route.
pub fn write_plain<T: Field>(out: &Out<T>, text: &mut String) -> Option<Vec<String>> {
    write_plain_node(out, text, 1)?;
    Some(match out {
        Out::Object(fields) => fields.iter().map(|(k, _)| k.clone()).collect(),
        _ => Vec::new(),
    })
}

/// [`write_plain`] of one node; `splits` is how many more times a large list may be written
/// as two halves on two threads (one: the first large list met from the root).
fn write_plain_node<T: Field>(out: &Out<T>, text: &mut String, splits: u32) -> Option<()> {
    match out {
        Out::Num(x) | Out::MaybeZero(x, _) => {
            if !x.is_finite() {
                return None;
            }
            text.push('"');
            let start = text.len();
            x.write_plain_string(text);
            if needs_escape(&text[start..]) {
                return None;
            }
            text.push('"');
        }
        Out::List(items) => {
            text.push('[');
            let split = if splits > 0 { split_point(items) } else { None };
            match split {
                None => write_items(items, text, splits)?,
                Some(middle) => write_halves(items.split_at(middle), text)?,
            }
            text.push(']');
        }
        Out::Object(fields) => {
            text.push('{');
            for (i, (key, value)) in fields.iter().enumerate() {
                if fields[..i].iter().any(|(k, _)| k == key) {
                    return None;
                }
                if i > 0 {
                    text.push(',');
                }
                write_json_string(key, text);
                text.push(':');
                write_plain_node(value, text, splits)?;
            }
            text.push('}');
        }
        Out::Int(i) => text.push_str(&i.to_string()),
        Out::Text(s) => {
            if says_not_finite(s) {
                return None;
            }
            write_json_string(s, text);
        }
        Out::Bool(b) => text.push_str(if *b { "true" } else { "false" }),
        Out::F64(x) if x.is_finite() => text.push_str(&crate::scalar::float_text(*x)),
        Out::F64(_) | Out::Null => text.push_str("null"),
        Out::Bounds(..) => {
            let Value::String(mid) = render_plain(out) else {
                return None;
            };
            if says_not_finite(&mid) {
                return None;
            }
            write_json_string(&mid, text);
        }
    }
    Some(())
}

/// Lists whose text is estimated at least this long are written in two halves on two
/// threads: printing is most of an f64 `run` on large data (ryu's digits of 48 000 doubles,
/// about 2.5 ms), and a GMP rational's decimal digits are costlier still; a thread costs
/// tens of microseconds.
const SPLIT_TEXT_BYTES: usize = 1 << 17;

/// Where to split `items` in two for two threads, if their text is long enough (estimated
/// from the first item's, so that deciding costs little).
fn split_point<T: Field>(items: &[Out<T>]) -> Option<usize> {
    let estimate = items.len() * (items.first()?.text_size_hint() + 1);
    (items.len() >= 2 && estimate >= SPLIT_TEXT_BYTES).then_some(items.len() / 2)
}

/// The items of a list, comma-separated, without the brackets.
fn write_items<T: Field>(items: &[Out<T>], text: &mut String, splits: u32) -> Option<()> {
    for (i, item) in items.iter().enumerate() {
        if i > 0 {
            text.push(',');
        }
        // Below a list too small to split, every list is smaller still.
        write_plain_node(item, text, splits.saturating_sub(1))?;
    }
    Some(())
}

/// Both halves of a list's items, the second written on a scoped thread into a text of
/// its own and appended: the same text as [`write_items`] of the whole. Written on this
/// thread alone if no thread can be started.
fn write_halves<T: Field>(
    (first, second): (&[Out<T>], &[Out<T>]),
    text: &mut String,
) -> Option<()> {
    let (head, tail) = std::thread::scope(|scope| {
        let tail = std::thread::Builder::new().spawn_scoped(scope, || {
            let mut tail = String::with_capacity(second.len() * (second[0].text_size_hint() + 1));
            write_items(second, &mut tail, 0).map(|()| tail)
        });
        let head = write_items(first, text, 0);
        (head, tail.ok().and_then(|handle| handle.join().ok()))
    });
    head?;
    text.push(',');
    match tail {
        Some(tail) => text.push_str(&tail?),
        // No thread could be started (or it did not finish): the second half here.
        None => write_items(second, text, 0)?,
    }
    Some(())
}

/// Whether serde_json escapes a character of `s` (a quote, a backslash or a control
/// character): only then is a string written through serde_json.
fn needs_escape(s: &str) -> bool {
    // A fold without an early exit, which the compiler vectorizes: every number of an
    // output passes through here, and none needs an escape.
    s.bytes().fold(false, |found, b| {
        found | (b == b'"') | (b == b'\\') | (b < 0x20)
    })
}

/// `s` as a JSON string, escaped exactly as serde_json escapes it.
fn write_json_string(s: &str, text: &mut String) {
    if needs_escape(s) {
        text.push_str(&Value::String(s.to_string()).to_string());
    } else {
        text.push('"');
        text.push_str(s);
        text.push('"');
    }
}

/// Render a ball tree: each number as {"value", "radius"}, two decimals with every point
/// of the ball inside [value − radius, value + radius] as printed ([`Ball::printed`]):
/// `value` carries the digits every point of the ball rounds to (the midpoint to two digits
/// when not even one is proven) and `radius` is measured from `value`, rounded up.
/// Fails, naming the field, when a ball is not finite (an unbounded enclosure).
pub fn render_proven(out: &Out<Ball>, path: &str) -> Result<Value, RunError> {
    Ok(match out {
        Out::Num(b) | Out::MaybeZero(b, _) => {
            let Some(printed) = b.printed() else {
                if b.mid().is_finite() && b.mid().clone().abs() > 1e290 {
                    return Err(RunError::Input(format!(
                        "output \"{path}\" is about {} in ball:{}: beyond the range of a ball's radius (an f64, about 1e308); use mpfr:<bits>",
                        format_float_digits(b.mid(), 3),
                        b.ctx()
                    )));
                }
                return Err(RunError::Input(format!(
                    "output \"{path}\" has no finite enclosure in ball:{}: an operation met a ball containing a singularity \
                     (a division by a ball around 0, a square root or logarithm of one reaching below 0); raise the precision",
                    b.ctx()
                )));
            };
            let mut m = Map::new();
            m.insert("value".into(), Value::String(printed.value));
            m.insert("radius".into(), Value::String(printed.radius));
            Value::Object(m)
        }
        Out::List(_) | Out::Object(_) => return render_tree(out, path, render_proven),
        Out::Bounds(b) => {
            let (lo, hi) = &**b;
            let printed = crate::scalar::ball::printed_interval(lo, hi, lo.prec().min(hi.prec()))
                .ok_or_else(|| {
                    RunError::Input(format!(
                        "output \"{path}\" has no finite enclosure at this precision; raise the precision"
                    ))
                })?;
            let mut m = Map::new();
            m.insert("value".into(), Value::String(printed.value));
            m.insert("radius".into(), Value::String(printed.radius));
            Value::Object(m)
        }
        other => render_plain_leaf(other),
    })
}

/// The text of a number known to lie in the ball `b`, with only digits the ball proves
/// (`mpfr:<bits>`'s contract, README "Precision is a result"):
/// - "0" for an exact zero;
/// - the [`Ball::proven_digits`]: the longest decimal every point of the ball rounds to, so
///   the exact value, rounded to the printed digits, is the printed string;
/// - for a ball that contains 0, of a quantity that may vanish (`may_be_zero`, an
///   [`Out::MaybeZero`]), the zero at the finest unit it proves, "0eK": every point of the
///   ball lies within ½·10^K of 0 (rounded at the unit 10^K, the value is 0).
///
/// `None` when the ball is not finite, or does not prove its first digit (such as
/// [0.94, 1.04], or a ball around 0 of a quantity that does not vanish).
pub fn proven_text(b: &Ball, may_be_zero: bool) -> Option<String> {
    if !b.mid().is_finite() || !b.rad().is_finite() {
        return None;
    }
    if b.rad() == 0.0 && b.mid().is_zero() {
        return Some("0".into());
    }
    let (digits, text) = b.proven_digits();
    if digits > 0 {
        return Some(text);
    }
    let (lo, hi) = (b.lower(), b.upper());
    if !may_be_zero
        || lo.is_sign_positive() && !lo.is_zero()
        || hi.is_sign_negative() && !hi.is_zero()
    {
        return None;
    }
    Some(format!("0e{}", zero_unit_exponent(&lo, &hi)))
}

/// The least K with [lo, hi] inside (−½·10^K, ½·10^K).
fn zero_unit_exponent(lo: &Float, hi: &Float) -> i64 {
    let reach = if lo.clone().abs() > hi.clone().abs() {
        lo.clone().abs()
    } else {
        hi.clone().abs()
    };
    if reach.is_zero() {
        return 0;
    }
    // 2·reach < 10^K ⇔ K > log₁₀(2·reach); start from an estimate and correct it exactly.
    let doubled = Float::with_val(reach.prec() + 2, &reach * 2u32);
    let mut k = doubled.to_f64().log10().floor() as i64;
    let below = |k: i64| {
        let ten = rug::Rational::from(rug::Integer::from(rug::Integer::u_pow_u(
            10,
            k.unsigned_abs() as u32,
        )));
        let unit = if k >= 0 { ten } else { ten.recip() };
        doubled.to_rational().is_some_and(|d| d < unit)
    };
    while !below(k) {
        k += 1;
    }
    while below(k - 1) {
        k -= 1;
    }
    k
}

/// Whether the f64 output `out` keeps a correct digit in the norm of each top-level field,
/// judged against `enclosure`, the same output in balls: `Some(Ok(()))` when proven for
/// every field (2·max |x − y| < max |y| for every y in the balls), `Some(Err(field))` when
/// proven not to hold for `field`, `None` when the balls are too wide to tell (or the two
/// outputs differ in shape). A field whose exact values are all 0 has no digits to lose.
pub fn f64_digit_in_norm(out: &Out<f64>, enclosure: &Out<Ball>) -> Option<Result<(), String>> {
    let (fields, balls) = (out.fields(), enclosure.fields());
    let mut undecided = false;
    for (name, value) in fields {
        let (_, reference) = balls.iter().find(|(k, _)| *k == name)?;
        let mut xs = Vec::new();
        value.numbers(&name, &mut xs);
        let ys = reference.enclosures()?;
        if xs.len() != ys.len() {
            return None;
        }
        // Bounds of the error max |x − y| and of the size max |y|, exactly in rationals.
        let zero = rug::Rational::new;
        let (mut error_hi, mut error_lo, mut size_hi, mut size_lo) =
            (zero(), zero(), zero(), zero());
        for ((_, x), (lo, hi)) in xs.iter().zip(&ys) {
            let x = rug::Rational::from_f64(**x)?;
            let (below, above) = (rug::Rational::from(&x - lo), rug::Rational::from(hi - &x));
            error_hi = error_hi.max(below.clone().abs().max(above.clone().abs()));
            // The distance from x to [lo, hi]: 0 inside.
            error_lo = error_lo.max((-below).max(-above).max(zero()));
            size_hi = size_hi.max(lo.clone().abs().max(hi.clone().abs()));
            if *lo > 0 || *hi < 0 {
                size_lo = size_lo.max(lo.clone().abs().min(hi.clone().abs()));
            }
        }
        if size_hi == 0 || error_hi.clone() * 2u32 < size_lo {
            continue;
        }
        if error_lo * 2u32 >= size_hi {
            return Some(Err(name));
        }
        undecided = true;
    }
    (!undecided).then_some(Ok(()))
}

impl Out<Ball> {
    /// Every number of a proven tree as its exact bounds [lo, hi], in order; `None` when one
    /// is not finite.
    pub fn enclosures(&self) -> Option<Vec<(rug::Rational, rug::Rational)>> {
        let mut found = Vec::new();
        self.collect_enclosures(&mut found)?;
        Some(found)
    }

    fn collect_enclosures(&self, found: &mut Vec<(rug::Rational, rug::Rational)>) -> Option<()> {
        match self {
            Out::Num(b) | Out::MaybeZero(b, _) => {
                found.push((b.lower().to_rational()?, b.upper().to_rational()?))
            }
            Out::Bounds(b) => found.push((b.0.to_rational()?, b.1.to_rational()?)),
            Out::List(items) => items.iter().try_for_each(|v| v.collect_enclosures(found))?,
            Out::Object(fields) => fields
                .iter()
                .try_for_each(|(_, v)| v.collect_enclosures(found))?,
            _ => {}
        }
        Some(())
    }
}

/// Render a ball tree for `mpfr:<bits>`: every number as a decimal string with the digits
/// its enclosure proves ([`proven_text`]). Fails, naming the field, when a number has no
/// finite enclosure or not even its first digit is proven (the user raises the precision).
pub fn render_digits(out: &Out<Ball>, path: &str) -> Result<Value, RunError> {
    Ok(match out {
        Out::Num(b) | Out::MaybeZero(b, _) => match proven_text(b, matches!(out, Out::MaybeZero(..))) {
            Some(text) => Value::String(text),
            None if b.mid().is_finite() && b.mid().clone().abs() > 1e290 => {
                return Err(RunError::Input(format!(
                    "output \"{path}\" is about {} at mpfr:{}: beyond the range of the error bound that proves its digits (an f64, about 1e308)",
                    format_float_digits(b.mid(), 3),
                    b.ctx()
                )))
            }
            None if !b.mid().is_finite() || !b.rad().is_finite() => {
                return Err(RunError::Input(format!(
                    "output \"{path}\" has no finite enclosure at mpfr:{}: the input is beyond this precision \
                     (an operation met a division by a value that may be 0, or a result beyond the range of the bounds); raise the precision",
                    b.ctx()
                )))
            }
            None => {
                return Err(RunError::Input(format!(
                    "output \"{path}\": not even its first digit is proven at mpfr:{} (it lies in [{}, {}]); raise the precision",
                    b.ctx(),
                    format_float_digits(&b.lower(), 3),
                    format_float_digits(&b.upper(), 3)
                )))
            }
        },
        Out::List(_) | Out::Object(_) => return render_tree(out, path, render_digits),
        Out::Bounds(b) => {
            let (lo, hi) = &**b;
            match crate::scalar::ball::interval_digits(lo, hi, lo.prec().min(hi.prec())) {
                (0, _) => {
                    return Err(RunError::Input(format!(
                        "output \"{path}\": not even its first digit is proven at {} bits (it lies in [{}, {}]); raise the precision",
                        lo.prec().min(hi.prec()),
                        format_float_digits(lo, 3),
                        format_float_digits(hi, 3)
                    )))
                }
                (_, text) => Value::String(text),
            }
        }
        other => render_plain_leaf(other),
    })
}

/// A list or an object of a ball tree, each item rendered by `render` with its path (the one
/// walk behind [`render_proven`] and [`render_digits`]); any other node by `render` itself.
fn render_tree(
    out: &Out<Ball>,
    path: &str,
    render: fn(&Out<Ball>, &str) -> Result<Value, RunError>,
) -> Result<Value, RunError> {
    Ok(match out {
        Out::List(items) => Value::Array(
            items
                .iter()
                .enumerate()
                .map(|(i, v)| render(v, &format!("{path}[{i}]")))
                .collect::<Result<_, _>>()?,
        ),
        Out::Object(fields) => Value::Object(
            fields
                .iter()
                .map(|(k, v)| render(v, &field_path(path, k)).map(|r| (k.clone(), r)))
                .collect::<Result<Map<_, _>, _>>()?,
        ),
        other => render(other, path)?,
    })
}

/// A leaf that is not a number of the tree's type, rendered as [`render_plain`] does.
fn render_plain_leaf<T>(out: &Out<T>) -> Value {
    match out {
        Out::Int(i) => Value::from(*i),
        Out::Text(s) => Value::String(s.clone()),
        Out::Bool(b) => Value::Bool(*b),
        Out::F64(x) => f64_value(*x),
        _ => Value::Null,
    }
}

/// The refusal of a result that is not finite in the chosen number type.
fn not_finite(path: &str, value: &str, scalar: &str) -> RunError {
    RunError::Input(format!(
        "output \"{path}\" is {value} in {scalar}: the input is beyond what this number type can carry (smaller magnitudes, or --scalar mpfr:<bits>)"
    ))
}

/// Whether a printed number says NaN or an infinity (as f64, MPFR or our own printing do).
fn says_not_finite(text: &str) -> bool {
    let t = text.trim_start_matches(['-', '+']).trim_matches('@');
    t.eq_ignore_ascii_case("nan")
        || t.eq_ignore_ascii_case("inf")
        || t.eq_ignore_ascii_case("infinity")
}

/// Refuse an output in which any number is NaN or infinite, naming the first such field.
///
/// The last check before anything is printed, whatever path built the output (typed
/// [`Out`] trees or JSON assembled directly): a non-finite result is never printed.
pub fn check_finite(value: &Value, path: &str, scalar: &str) -> Result<(), RunError> {
    let mut steps = Vec::new();
    let Some(text) = first_not_finite(value, &mut steps) else {
        return Ok(());
    };
    // The path is spelt out only for the refusal: no string per number on the way.
    let mut at = path.to_string();
    for step in steps {
        at = match step {
            Step::Index(i) => format!("{at}[{i}]"),
            Step::Key(k) => field_path(&at, k),
        };
    }
    Err(not_finite(&at, text, scalar))
}

/// One step from a JSON node to a child.
enum Step<'a> {
    Index(usize),
    Key(&'a str),
}

/// The first string of `value` that says NaN or an infinity, with the steps to it in `steps`.
fn first_not_finite<'a>(value: &'a Value, steps: &mut Vec<Step<'a>>) -> Option<&'a str> {
    match value {
        Value::String(s) if says_not_finite(s) => Some(s),
        Value::Array(items) => items
            .iter()
            .enumerate()
            .find_map(|(i, v)| descend(Step::Index(i), v, steps)),
        Value::Object(map) => map
            .iter()
            .find_map(|(k, v)| descend(Step::Key(k), v, steps)),
        _ => None,
    }
}

/// [`first_not_finite`] in the child `value` reached by `step`, the step kept only if found.
fn descend<'a>(step: Step<'a>, value: &'a Value, steps: &mut Vec<Step<'a>>) -> Option<&'a str> {
    steps.push(step);
    let found = first_not_finite(value, steps);
    if found.is_none() {
        steps.pop();
    }
    found
}
