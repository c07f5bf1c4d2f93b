//! A small expression language for parametric curves, evaluated with Taylor-mode AD.
//!
//! Grammar (the usual precedences; `^` binds tighter than unary minus and is right-associative):
//!
//! ```text
//! curve  := '[' expr (',' expr)* ']'
//! expr   := term (('+' | '-') term)*
//! term   := unary (('*' | '/') unary)*
//! unary  := ('-' | '+') unary | power
//! power  := atom ('^' unary)?
//! atom   := number | 't' | 'pi' | name '(' expr ')' | '(' expr ')'
//! name   := sin | cos | tan | exp | ln | sqrt | atan
//! ```
//!
//! Numbers are read exactly (`7.2` is 36/5) and rounded once into the working precision, so an
//! expression means the same curve in f64 and in MPFR. Evaluation is generic over [`Real`]: at
//! a [`Taylor`] variable it returns the curve's derivatives at a point to any order, exact to
//! the working precision (no finite differences). An integer exponent is repeated
//! multiplication (`t^3` is defined for t < 0); any other exponent is exp(b·ln a).

use super::taylor::Taylor;
use crate::scalar::parse::{denotes_integer, parse_rational};
use crate::scalar::{powi, BigRational, Real};

/// The deepest expression accepted: operations nested inside one another (a chain
/// `t+t+…+t` nests one level per operator) and parentheses inside one another. Parsing,
/// compiling and evaluating recurse once per level, so a bound keeps any input from
/// overflowing the stack; real curves nest a few dozen levels at most.
pub const MAX_DEPTH: usize = 500;

/// A syntax or name error, with the 1-based character position where it was found.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("at character {position}: {message}")]
pub struct ExprError {
    /// The 1-based character position.
    pub position: usize,
    /// What is wrong there.
    pub message: String,
}

/// The functions the language knows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Func {
    /// sin.
    Sin,
    /// cos.
    Cos,
    /// tan.
    Tan,
    /// exp.
    Exp,
    /// ln (natural logarithm).
    Ln,
    /// sqrt.
    Sqrt,
    /// atan.
    Atan,
}

impl Func {
    const ALL: [(&'static str, Func); 7] = [
        ("sin", Func::Sin),
        ("cos", Func::Cos),
        ("tan", Func::Tan),
        ("exp", Func::Exp),
        ("ln", Func::Ln),
        ("sqrt", Func::Sqrt),
        ("atan", Func::Atan),
    ];
}

/// A parsed scalar expression in t.
#[derive(Clone, Debug, PartialEq)]
pub enum Expr {
    /// A number, exact as written.
    Number(BigRational),
    /// The parameter t.
    T,
    /// π.
    Pi,
    /// −a.
    Neg(Box<Expr>),
    /// a + b.
    Add(Box<Expr>, Box<Expr>),
    /// a − b.
    Sub(Box<Expr>, Box<Expr>),
    /// a · b.
    Mul(Box<Expr>, Box<Expr>),
    /// a / b.
    Div(Box<Expr>, Box<Expr>),
    /// a ^ b.
    Pow(Box<Expr>, Box<Expr>),
    /// A function applied to its argument.
    Call(Func, Box<Expr>),
}

impl Expr {
    /// The value at `t` in the number type of `t` (a plain scalar or a Taylor series).
    pub fn eval<X: Real>(&self, t: &X) -> X {
        self.compile::<X>(&t.ctx()).eval(t)
    }

    /// Whether the expression depends on t (a constant such as `pi/8` does not).
    pub fn mentions_t(&self) -> bool {
        match self {
            Expr::T => true,
            Expr::Number(_) | Expr::Pi => false,
            Expr::Neg(a) | Expr::Call(_, a) => a.mentions_t(),
            Expr::Add(a, b)
            | Expr::Sub(a, b)
            | Expr::Mul(a, b)
            | Expr::Div(a, b)
            | Expr::Pow(a, b) => a.mentions_t() || b.mentions_t(),
        }
    }

    /// The value and the first `order` derivatives at t₀.
    pub fn derivatives<T: Real>(&self, t0: &T, order: usize) -> Vec<T> {
        self.eval(&Taylor::variable(t0.clone(), order))
            .with_order(order)
            .derivatives()
    }
}

/// A real number given exactly: a rational, or a constant expression such as `pi/8`
/// (exact as a formula, rounded only when it is evaluated in a number type).
#[derive(Clone, Debug, PartialEq)]
pub enum ExactReal {
    /// A rational number.
    Exact(BigRational),
    /// A constant expression (it does not mention t).
    Expr(Expr),
}

impl From<BigRational> for ExactReal {
    fn from(q: BigRational) -> Self {
        ExactReal::Exact(q)
    }
}

impl From<i64> for ExactReal {
    fn from(n: i64) -> Self {
        ExactReal::Exact(BigRational::from_integer(n.into()))
    }
}

impl ExactReal {
    /// A number read exactly ([`parse_rational`]: `"0.25"`, `"1/3"`, `"1e-3"`), else a constant
    /// expression in the curve language (`"4*pi"`, `"sqrt(2)/2"`).
    ///
    /// # Errors
    /// The parser's message for text that is neither, or "expected a constant, found an
    /// expression in t" for an expression that mentions t.
    pub fn parse(text: &str) -> Result<Self, String> {
        if let Ok(q) = parse_rational(text) {
            return Ok(ExactReal::Exact(q));
        }
        let e = parse_expr(text).map_err(|e| e.to_string())?;
        if e.mentions_t() {
            return Err("expected a constant, found an expression in t".into());
        }
        Ok(ExactReal::Expr(e))
    }

    /// A double taken exactly (every finite double is a rational); `None` for NaN and ±∞.
    pub fn from_f64(x: f64) -> Option<Self> {
        BigRational::from_float(x).map(ExactReal::Exact)
    }

    /// The value in the number type `T` (rounded once for a rational; for an expression,
    /// each operation rounded in `T`, so a ball encloses it).
    pub fn eval<T: Real>(&self, ctx: &T::Ctx) -> T {
        match self {
            ExactReal::Exact(q) => T::from_rational(q, ctx),
            ExactReal::Expr(e) => e.eval(&T::zero_in(ctx)),
        }
    }
}

/// An [`Expr`] with its numbers rounded once into a context: what evaluation runs on.
#[derive(Clone, Debug)]
pub enum Compiled<T> {
    /// A number rounded into the context.
    Const(T),
    /// The parameter t.
    T,
    /// −a.
    Neg(Box<Compiled<T>>),
    /// a + b.
    Add(Box<Compiled<T>>, Box<Compiled<T>>),
    /// a − b.
    Sub(Box<Compiled<T>>, Box<Compiled<T>>),
    /// a · b.
    Mul(Box<Compiled<T>>, Box<Compiled<T>>),
    /// a / b.
    Div(Box<Compiled<T>>, Box<Compiled<T>>),
    /// An integer power by repeated squaring (negative: reciprocal).
    PowInt(Box<Compiled<T>>, i64),
    /// a^b = exp(b ln a).
    Pow(Box<Compiled<T>>, Box<Compiled<T>>),
    /// A function applied to its argument.
    Call(Func, Box<Compiled<T>>),
}

impl Expr {
    /// Round every number into `ctx` once.
    pub fn compile<T: Real>(&self, ctx: &T::Ctx) -> Compiled<T> {
        let c = |e: &Expr| Box::new(e.compile::<T>(ctx));
        match self {
            Expr::Number(q) => Compiled::Const(T::from_rational(q, ctx)),
            Expr::T => Compiled::T,
            Expr::Pi => Compiled::Const(T::pi(ctx)),
            Expr::Neg(a) => Compiled::Neg(c(a)),
            Expr::Add(a, b) => Compiled::Add(c(a), c(b)),
            Expr::Sub(a, b) => Compiled::Sub(c(a), c(b)),
            Expr::Mul(a, b) => Compiled::Mul(c(a), c(b)),
            Expr::Div(a, b) => Compiled::Div(c(a), c(b)),
            Expr::Pow(a, b) => match b.as_ref() {
                Expr::Number(q) => match denotes_integer(q).filter(|n| n.unsigned_abs() <= 1 << 20)
                {
                    Some(n) => Compiled::PowInt(c(a), n),
                    None => Compiled::Pow(c(a), c(b)),
                },
                _ => Compiled::Pow(c(a), c(b)),
            },
            Expr::Call(f, a) => Compiled::Call(*f, c(a)),
        }
    }
}

impl<X: Real> Compiled<X> {
    /// The value at `t`; at a [`Taylor`] variable (X = `Taylor<T>`) it carries the derivatives.
    pub fn eval(&self, t: &X) -> X {
        match self {
            Compiled::Const(v) => v.clone(),
            Compiled::T => t.clone(),
            Compiled::Neg(a) => -a.eval(t),
            Compiled::Add(a, b) => a.eval(t) + &b.eval(t),
            Compiled::Sub(a, b) => a.eval(t) - &b.eval(t),
            Compiled::Mul(a, b) => a.eval(t) * &b.eval(t),
            Compiled::Div(a, b) => a.eval(t) / &b.eval(t),
            Compiled::PowInt(a, n) => {
                let p = powi(&a.eval(t), n.unsigned_abs() as u32);
                if *n < 0 {
                    X::one_in(&t.ctx()) / &p
                } else {
                    p
                }
            }
            Compiled::Pow(a, b) => (b.eval(t) * &a.eval(t).ln()).exp(),
            Compiled::Call(f, a) => {
                let x = a.eval(t);
                match f {
                    Func::Sin => x.sin_cos().0,
                    Func::Cos => x.sin_cos().1,
                    Func::Tan => {
                        let (s, c) = x.sin_cos();
                        s / &c
                    }
                    Func::Exp => x.exp(),
                    Func::Ln => x.ln(),
                    Func::Sqrt => x.sqrt(),
                    Func::Atan => x.atan2(&X::one_in(&t.ctx())),
                }
            }
        }
    }
}

impl<T: Real> Compiled<Taylor<T>> {
    /// The value at `t` alone, without series: the operations [`Compiled::eval`] performs on
    /// the constant terms at a variable of order 0, in the same order and with the same
    /// roundings (a quotient is a product with the reciprocal, as `Taylor`'s division by a
    /// constant series is), so the result is bit for bit the value `eval` gives, without its
    /// vectors. The error searches of paper 001 evaluate curves at millions of points.
    pub fn eval_value(&self, t: &T) -> T {
        let one = || T::one_in(&t.ctx());
        let reciprocal_times = |x: T, d: &T| x * &(one() / d);
        match self {
            Compiled::Const(v) => v.value().clone(),
            Compiled::T => t.clone(),
            Compiled::Neg(a) => -a.eval_value(t),
            Compiled::Add(a, b) => a.eval_value(t) + &b.eval_value(t),
            Compiled::Sub(a, b) => a.eval_value(t) - &b.eval_value(t),
            Compiled::Mul(a, b) => a.eval_value(t) * &b.eval_value(t),
            Compiled::Div(a, b) => reciprocal_times(a.eval_value(t), &b.eval_value(t)),
            Compiled::PowInt(a, n) => {
                let p = powi(&a.eval_value(t), n.unsigned_abs() as u32);
                if *n < 0 {
                    reciprocal_times(one(), &p)
                } else {
                    p
                }
            }
            Compiled::Pow(a, b) => (b.eval_value(t) * &a.eval_value(t).ln()).exp(),
            Compiled::Call(f, a) => {
                let x = a.eval_value(t);
                match f {
                    Func::Sin => x.sin(),
                    Func::Cos => x.cos(),
                    Func::Tan => {
                        let (s, c) = x.sin_cos();
                        reciprocal_times(s, &c)
                    }
                    Func::Exp => x.exp(),
                    Func::Ln => x.ln(),
                    Func::Sqrt => x.sqrt(),
                    Func::Atan => x.atan2(&one()),
                }
            }
        }
    }
}

/// Parse a single scalar expression.
///
/// # Errors
/// [`ExprError`] at the first problem: a syntax error, an unknown name, a number
/// [`parse_rational`] rejects, nesting deeper than [`MAX_DEPTH`], or text after the expression.
pub fn parse_expr(text: &str) -> Result<Expr, ExprError> {
    let mut p = Parser::new(text);
    let e = p.expr()?;
    p.expect_end()?;
    Ok(e)
}

/// Parse a vector `[e1, e2, …]` of scalar expressions.
///
/// # Errors
/// [`ExprError`] as [`parse_expr`] for each component, and when the text does not start with
/// `[`, a component is not followed by `,` or `]`, or text follows the closing `]`.
pub fn parse_vector(text: &str) -> Result<Vec<Expr>, ExprError> {
    let mut p = Parser::new(text);
    p.skip_space();
    p.expect('[', "a curve starts with '['")?;
    let mut items = vec![p.expr()?];
    loop {
        p.skip_space();
        match p.peek() {
            Some(',') => {
                p.pos += 1;
                items.push(p.expr()?);
            }
            Some(']') => {
                p.pos += 1;
                break;
            }
            _ => return Err(p.error("expected ',' or ']'")),
        }
    }
    p.expect_end()?;
    Ok(items)
}

struct Parser {
    chars: Vec<char>,
    pos: usize,
    /// The depth of the expression tree the last parse step returned (a leaf is 1).
    depth: usize,
    /// Parentheses and function calls open around the current position.
    open: usize,
}

impl Parser {
    fn new(text: &str) -> Self {
        Parser {
            chars: text.chars().collect(),
            pos: 0,
            depth: 0,
            open: 0,
        }
    }
    /// Record that the tree just built has depth `depth`, refusing one beyond [`MAX_DEPTH`].
    fn nest(&mut self, depth: usize) -> Result<(), ExprError> {
        if depth > MAX_DEPTH {
            return Err(self.too_deep());
        }
        self.depth = depth;
        Ok(())
    }
    /// Parse a nested part (inside parentheses, a call, a sign or an exponent) one level
    /// further in, refusing to recurse past [`MAX_DEPTH`].
    fn inner(&mut self, part: fn(&mut Self) -> Result<Expr, ExprError>) -> Result<Expr, ExprError> {
        if self.open >= MAX_DEPTH {
            return Err(self.too_deep());
        }
        self.open += 1;
        let e = part(self);
        self.open -= 1;
        e
    }
    fn too_deep(&self) -> ExprError {
        self.error(format!(
            "the expression nests deeper than {MAX_DEPTH} levels"
        ))
    }
    fn error(&self, message: impl Into<String>) -> ExprError {
        ExprError {
            position: self.pos + 1,
            message: message.into(),
        }
    }
    fn peek(&self) -> Option<char> {
        self.chars.get(self.pos).copied()
    }
    fn skip_space(&mut self) {
        while self.peek().is_some_and(char::is_whitespace) {
            self.pos += 1;
        }
    }
    fn expect(&mut self, c: char, what: &str) -> Result<(), ExprError> {
        self.skip_space();
        if self.peek() == Some(c) {
            self.pos += 1;
            Ok(())
        } else {
            Err(self.error(what))
        }
    }
    fn expect_end(&mut self) -> Result<(), ExprError> {
        self.skip_space();
        match self.peek() {
            None => Ok(()),
            Some(c) => Err(self.error(format!("unexpected {c:?}"))),
        }
    }
    fn expr(&mut self) -> Result<Expr, ExprError> {
        let mut left = self.term()?;
        loop {
            let left_depth = self.depth;
            self.skip_space();
            let op: fn(Box<Expr>, Box<Expr>) -> Expr = match self.peek() {
                Some('+') => Expr::Add,
                Some('-') => Expr::Sub,
                _ => return Ok(left),
            };
            self.pos += 1;
            let right = self.term()?;
            self.nest(1 + left_depth.max(self.depth))?;
            left = op(Box::new(left), Box::new(right));
        }
    }
    fn term(&mut self) -> Result<Expr, ExprError> {
        let mut left = self.unary()?;
        loop {
            let left_depth = self.depth;
            self.skip_space();
            let op: fn(Box<Expr>, Box<Expr>) -> Expr = match self.peek() {
                Some('*') => Expr::Mul,
                Some('/') => Expr::Div,
                _ => return Ok(left),
            };
            self.pos += 1;
            let right = self.unary()?;
            self.nest(1 + left_depth.max(self.depth))?;
            left = op(Box::new(left), Box::new(right));
        }
    }
    fn unary(&mut self) -> Result<Expr, ExprError> {
        self.skip_space();
        match self.peek() {
            Some('-') => {
                self.pos += 1;
                let operand = self.inner(Self::unary)?;
                self.nest(self.depth + 1)?;
                Ok(Expr::Neg(Box::new(operand)))
            }
            Some('+') => {
                self.pos += 1;
                self.inner(Self::unary)
            }
            _ => self.power(),
        }
    }
    fn power(&mut self) -> Result<Expr, ExprError> {
        let base = self.atom()?;
        self.skip_space();
        if self.peek() == Some('^') {
            let base_depth = self.depth;
            self.pos += 1;
            let exponent = self.inner(Self::unary)?;
            self.nest(1 + base_depth.max(self.depth))?;
            return Ok(Expr::Pow(Box::new(base), Box::new(exponent)));
        }
        Ok(base)
    }
    fn atom(&mut self) -> Result<Expr, ExprError> {
        self.skip_space();
        let start = self.pos;
        match self.peek() {
            None => Err(self.error("unexpected end of the expression")),
            Some('(') => {
                self.pos += 1;
                let e = self.inner(Self::expr)?;
                self.expect(')', "expected ')'")?;
                Ok(e)
            }
            Some(c) if c.is_ascii_digit() || c == '.' => {
                while self.peek().is_some_and(|c| c.is_ascii_digit() || c == '.') {
                    self.pos += 1;
                }
                // An exponent: e or E, an optional sign, digits.
                if matches!(self.peek(), Some('e' | 'E')) {
                    let save = self.pos;
                    self.pos += 1;
                    if matches!(self.peek(), Some('+' | '-')) {
                        self.pos += 1;
                    }
                    if self.peek().is_some_and(|c| c.is_ascii_digit()) {
                        while self.peek().is_some_and(|c| c.is_ascii_digit()) {
                            self.pos += 1;
                        }
                    } else {
                        self.pos = save;
                    }
                }
                let text: String = self.chars[start..self.pos].iter().collect();
                self.nest(1)?;
                parse_rational(&text)
                    .map(Expr::Number)
                    .map_err(|e| ExprError {
                        position: start + 1,
                        message: format!("bad number {text:?}: {e}"),
                    })
            }
            Some(c) if c.is_ascii_alphabetic() || c == '_' => {
                while self
                    .peek()
                    .is_some_and(|c| c.is_ascii_alphanumeric() || c == '_')
                {
                    self.pos += 1;
                }
                let name: String = self.chars[start..self.pos].iter().collect();
                match name.as_str() {
                    "t" => return self.nest(1).map(|_| Expr::T),
                    "pi" => return self.nest(1).map(|_| Expr::Pi),
                    _ => {}
                }
                let Some(&(_, f)) = Func::ALL.iter().find(|(n, _)| *n == name) else {
                    return Err(ExprError {
                        position: start + 1,
                        message: format!(
                            "unknown name {name:?} (the variable is t; functions: sin, cos, tan, exp, ln, sqrt, atan; constant: pi)"
                        ),
                    });
                };
                self.expect('(', &format!("expected '(' after {name}"))?;
                let arg = self.inner(Self::expr)?;
                self.expect(')', "expected ')'")?;
                self.nest(self.depth + 1)?;
                Ok(Expr::Call(f, Box::new(arg)))
            }
            Some(c) => Err(self.error(format!("unexpected {c:?}"))),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_test_curve_of_eq_23_and_its_derivatives() {
        let v = parse_vector("[1.5*sin(7.2*t), cos(9*t), exp(cos(1.8*t))]").unwrap();
        let t = 0.4f64;
        let x = v[0].derivatives(&t, 4);
        let w = 7.2f64;
        let expect = [
            1.5 * (w * t).sin(),
            1.5 * w * (w * t).cos(),
            -1.5 * w * w * (w * t).sin(),
            -1.5 * w.powi(3) * (w * t).cos(),
            1.5 * w.powi(4) * (w * t).sin(),
        ];
        for k in 0..5 {
            assert!(
                (x[k] - expect[k]).abs() < 1e-11 * expect[k].abs().max(1.0),
                "{k}"
            );
        }
        let z = v[2].derivatives(&t, 1);
        let e = (1.8 * t).cos().exp();
        assert!((z[1] - e * (-1.8 * (1.8 * t).sin())).abs() < 1e-13);
    }

    #[test]
    fn precedence_and_powers() {
        let e = parse_expr("-t^2 + 2*t^-1 - 8/2/2 + 2^3^2/2^8").unwrap();
        let t = 3.0f64;
        let expected = -9.0 + 2.0 / 3.0 - 2.0 + 512.0 / 256.0;
        assert!((e.eval(&t) - expected).abs() < 1e-12);
        let r = parse_expr("t^0.5").unwrap();
        assert!((r.eval(&4.0f64) - 2.0).abs() < 1e-15);
        assert_eq!(
            parse_expr("pi").unwrap().eval(&0.0f64),
            std::f64::consts::PI
        );
    }

    #[test]
    fn errors_name_the_position() {
        let e = parse_vector("[sin(t), sinh(t), 1]").unwrap_err();
        assert_eq!(e.position, 10);
        assert!(e.message.contains("unknown name \"sinh\""), "{e}");
        assert_eq!(parse_expr("1 + * t").unwrap_err().position, 5);
        assert_eq!(parse_expr("(t + 1").unwrap_err().position, 7);
        assert!(parse_vector("sin(t)").is_err());
        assert!(parse_expr("t t").is_err());
    }

    #[test]
    fn deep_nesting_is_an_error_not_a_stack_overflow() {
        let deep =
            |open: &str, close: &str, n: usize| format!("{}t{}", open.repeat(n), close.repeat(n));
        for text in [
            deep("(", ")", 100_000),
            deep("sin(", ")", 100_000),
            deep("-", "", 100_000),
            deep("2^", "", 100_000),
            format!("t{}", "+t".repeat(100_000)),
            format!("t{}", "*t".repeat(100_000)),
        ] {
            let e = parse_expr(&text).unwrap_err();
            assert!(e.message.contains("nests deeper than 500"), "{e}");
        }
        // Up to the bound every form parses and evaluates.
        let ok = |text: String| parse_expr(&text).unwrap().eval(&0.5f64);
        assert_eq!(ok(deep("(", ")", MAX_DEPTH - 1)), 0.5);
        assert_eq!(ok(deep("-", "", MAX_DEPTH - 2)), 0.5);
        assert_eq!(ok(format!("t{}", "*1".repeat(MAX_DEPTH - 1))), 0.5);
    }
}
