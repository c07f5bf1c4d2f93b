//! The JSON tree of a `run` input (RFC 8259), borrowing from the input text.
//!
//! Every number keeps its decimal text as a slice of the input (the exact value of `0.1` is
//! 1/10, read later by the run's number type), and every string without escapes is a slice
//! too: no allocation per number and 32 bytes per node, where serde_json's tree with
//! `arbitrary_precision` takes a string allocation per number and 72 bytes per node. An f64
//! `run hermite` on a 2000-dimensional point reads 52 000 numbers; the serde tree was about
//! 45 % of its instructions.
//!
//! The grammar is JSON's, exactly as serde_json accepts it (the tests compare the two on
//! valid and broken texts): literals `true`, `false`, `null`; numbers
//! `-?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?`; strings without raw control characters,
//! whose escapes serde_json decodes (so a lone surrogate is refused as it refuses it); at most
//! 127 nested arrays and objects (serde_json's recursion limit). A text this parser refuses
//! is handed to serde_json for its error message, so the messages are serde_json's.
//!
//! While parsing, the first key that an object repeats is recorded (serde_json would keep the
//! last of two equal keys and so silently drop the first value).

use std::borrow::Cow;
use std::collections::HashSet;

/// A JSON value whose numbers and plain strings borrow from the input text.
#[derive(Clone, Debug, PartialEq)]
pub enum Value<'a> {
    Null,
    Bool(bool),
    /// A JSON number, as its text.
    Number(Number<'a>),
    String(Cow<'a, str>),
    Array(Vec<Value<'a>>),
    Object(Map<'a>),
}

/// The text of a JSON number, as written in the input.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Number<'a>(&'a str);

impl<'a> Number<'a> {
    /// The number's text (`-0.25e3`).
    pub fn as_str(&self) -> &'a str {
        self.0
    }
}

/// A JSON object: its members in the order of the text, no key twice (a document whose
/// object repeats a key is refused by [`parse`]'s caller).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Map<'a> {
    members: Vec<(Cow<'a, str>, Value<'a>)>,
}

impl<'a> Map<'a> {
    /// The value of member `key`.
    pub fn get(&self, key: &str) -> Option<&Value<'a>> {
        self.members.iter().find(|(k, _)| k == key).map(|(_, v)| v)
    }
    /// The keys, in the order of the text.
    pub fn keys(&self) -> impl Iterator<Item = &str> {
        self.members.iter().map(|(k, _)| k.as_ref())
    }
}

impl<'a> Value<'a> {
    /// The items of an array.
    pub fn as_array(&self) -> Option<&Vec<Value<'a>>> {
        match self {
            Value::Array(items) => Some(items),
            _ => None,
        }
    }
    /// The members of an object.
    pub fn as_object(&self) -> Option<&Map<'a>> {
        match self {
            Value::Object(map) => Some(map),
            _ => None,
        }
    }
}

/// A parsed document and the first key an object of it repeats, with the byte offset just
/// after that key's closing quote.
pub struct Parsed<'a> {
    pub value: Value<'a>,
    pub repeated_key: Option<(String, usize)>,
}

/// Why the text is not JSON: the byte offset where the parser stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Malformed {
    pub offset: usize,
}

/// serde_json's recursion limit: 127 nested arrays and objects are accepted, 128 are not.
const MAX_DEPTH: usize = 127;
/// Objects of more members than this look up repeated keys in a hash set rather than by a
/// linear scan (a linear scan of a 10⁵-key object would be quadratic).
const LINEAR_KEY_SCAN: usize = 16;

/// Parse a whole JSON text (one value, surrounded by whitespace only).
pub fn parse(text: &str) -> Result<Parsed<'_>, Malformed> {
    let mut parser = Parser {
        text,
        bytes: text.as_bytes(),
        at: 0,
        depth: 0,
        repeated_key: None,
    };
    parser.skip_whitespace();
    let value = parser.value()?;
    parser.skip_whitespace();
    if parser.at != parser.bytes.len() {
        return Err(parser.malformed());
    }
    Ok(Parsed {
        value,
        repeated_key: parser.repeated_key,
    })
}

struct Parser<'a> {
    text: &'a str,
    bytes: &'a [u8],
    at: usize,
    depth: usize,
    repeated_key: Option<(String, usize)>,
}

impl<'a> Parser<'a> {
    fn malformed(&self) -> Malformed {
        Malformed { offset: self.at }
    }

    fn peek(&self) -> Option<u8> {
        self.bytes.get(self.at).copied()
    }

    fn skip_whitespace(&mut self) {
        while matches!(self.peek(), Some(b' ' | b'\t' | b'\n' | b'\r')) {
            self.at += 1;
        }
    }

    /// Consume `byte` (after whitespace) or fail.
    fn expect(&mut self, byte: u8) -> Result<(), Malformed> {
        self.skip_whitespace();
        if self.peek() != Some(byte) {
            return Err(self.malformed());
        }
        self.at += 1;
        Ok(())
    }

    fn value(&mut self) -> Result<Value<'a>, Malformed> {
        match self.peek() {
            Some(b'{') => self.nested(Self::object),
            Some(b'[') => self.nested(Self::array),
            Some(b'"') => Ok(Value::String(self.string()?)),
            Some(b't') => self.literal("true", Value::Bool(true)),
            Some(b'f') => self.literal("false", Value::Bool(false)),
            Some(b'n') => self.literal("null", Value::Null),
            Some(b'-' | b'0'..=b'9') => Ok(Value::Number(self.number()?)),
            _ => Err(self.malformed()),
        }
    }

    fn literal(&mut self, word: &str, value: Value<'a>) -> Result<Value<'a>, Malformed> {
        if !self.bytes[self.at..].starts_with(word.as_bytes()) {
            return Err(self.malformed());
        }
        self.at += word.len();
        Ok(value)
    }

    /// An array or object one level deeper, refused beyond [`MAX_DEPTH`].
    fn nested(
        &mut self,
        inner: fn(&mut Self) -> Result<Value<'a>, Malformed>,
    ) -> Result<Value<'a>, Malformed> {
        if self.depth == MAX_DEPTH {
            return Err(self.malformed());
        }
        self.depth += 1;
        self.at += 1; // the opening bracket
        let value = inner(self)?;
        self.depth -= 1;
        Ok(value)
    }

    fn array(&mut self) -> Result<Value<'a>, Malformed> {
        let mut items = Vec::new();
        self.skip_whitespace();
        if self.peek() == Some(b']') {
            self.at += 1;
            return Ok(Value::Array(items));
        }
        loop {
            self.skip_whitespace();
            items.push(self.value()?);
            self.skip_whitespace();
            match self.peek() {
                Some(b',') => self.at += 1,
                Some(b']') => {
                    self.at += 1;
                    return Ok(Value::Array(items));
                }
                _ => return Err(self.malformed()),
            }
        }
    }

    fn object(&mut self) -> Result<Value<'a>, Malformed> {
        let mut members: Vec<(Cow<'a, str>, Value<'a>)> = Vec::new();
        let mut seen: Option<HashSet<String>> = None;
        self.skip_whitespace();
        if self.peek() == Some(b'}') {
            self.at += 1;
            return Ok(Value::Object(Map { members }));
        }
        loop {
            self.skip_whitespace();
            if self.peek() != Some(b'"') {
                return Err(self.malformed());
            }
            let key = self.string()?;
            self.note_repeat(&key, &members, &mut seen);
            self.expect(b':')?;
            self.skip_whitespace();
            let value = self.value()?;
            members.push((key, value));
            self.skip_whitespace();
            match self.peek() {
                Some(b',') => self.at += 1,
                Some(b'}') => {
                    self.at += 1;
                    return Ok(Value::Object(Map { members }));
                }
                _ => return Err(self.malformed()),
            }
        }
    }

    /// Record `key` (just parsed) if the object already has it and no earlier key of the
    /// document repeated.
    fn note_repeat(
        &mut self,
        key: &str,
        members: &[(Cow<'a, str>, Value<'a>)],
        seen: &mut Option<HashSet<String>>,
    ) {
        let repeated = if members.len() < LINEAR_KEY_SCAN {
            members.iter().any(|(k, _)| k == key)
        } else {
            let set =
                seen.get_or_insert_with(|| members.iter().map(|(k, _)| k.to_string()).collect());
            !set.insert(key.to_string())
        };
        if repeated && self.repeated_key.is_none() {
            self.repeated_key = Some((key.to_string(), self.at));
        }
    }

    /// A string at the opening quote: borrowed when it has no escape, decoded by serde_json
    /// (its escapes and its refusal of lone surrogates) when it has.
    fn string(&mut self) -> Result<Cow<'a, str>, Malformed> {
        let start = self.at;
        self.at += 1;
        let mut escaped = false;
        loop {
            match self.peek() {
                None => return Err(self.malformed()),
                Some(b'"') => break,
                Some(b'\\') => {
                    escaped = true;
                    self.at += 2;
                }
                Some(0x00..=0x1f) => return Err(self.malformed()),
                Some(_) => self.at += 1,
            }
        }
        self.at += 1; // the closing quote
        let quoted = self.text.get(start..self.at).ok_or(self.malformed())?;
        if escaped {
            serde_json::from_str::<String>(quoted)
                .map(Cow::Owned)
                .map_err(|_| Malformed { offset: start })
        } else {
            Ok(Cow::Borrowed(&quoted[1..quoted.len() - 1]))
        }
    }

    fn digits(&mut self) -> usize {
        let start = self.at;
        while matches!(self.peek(), Some(b'0'..=b'9')) {
            self.at += 1;
        }
        self.at - start
    }

    fn number(&mut self) -> Result<Number<'a>, Malformed> {
        let start = self.at;
        if self.peek() == Some(b'-') {
            self.at += 1;
        }
        match self.peek() {
            Some(b'0') => self.at += 1,
            Some(b'1'..=b'9') => {
                self.digits();
            }
            _ => return Err(self.malformed()),
        }
        if self.peek() == Some(b'.') {
            self.at += 1;
            if self.digits() == 0 {
                return Err(self.malformed());
            }
        }
        if matches!(self.peek(), Some(b'e' | b'E')) {
            self.at += 1;
            if matches!(self.peek(), Some(b'+' | b'-')) {
                self.at += 1;
            }
            if self.digits() == 0 {
                return Err(self.malformed());
            }
        }
        // A digit right after a leading 0 ("01") is not JSON; the caller then finds the
        // digit where a separator belongs and refuses the text.
        Ok(Number(&self.text[start..self.at]))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Whether serde_json (as this crate builds it) accepts `text`.
    fn serde_accepts(text: &str) -> bool {
        serde_json::from_str::<serde_json::Value>(text).is_ok()
    }

    #[test]
    fn accepts_and_refuses_what_serde_json_does() {
        let texts = [
            "{}",
            "[]",
            " {\"a\" : [1, -0, 0.5, 1e3, 1E+3, -2.5e-7, 12345678901234567890123]} ",
            "{\"a\": \"x\\\"y\\u00e9\\n\", \"b\": [true, false, null, {}]}",
            "\"\\ud83d\\ude00\"",
            "\"\\ud83d\"",
            "\"\\uDC00x\"",
            "\"a\u{1}b\"",
            "\"tab\there\"",
            "\"bad \\x escape\"",
            "01",
            "[01]",
            "-",
            "1.",
            ".5",
            "+1",
            "1e",
            "1e+",
            "[1,]",
            "{\"a\":1,}",
            "{\"a\" 1}",
            "{1: 2}",
            "[1 2]",
            "tru",
            "nul",
            "[true false]",
            "",
            "   ",
            "{} {}",
            "{}x",
            "[\"unterminated]",
            "\u{feff}{}",
            "{\"a\":[1,{\"b\":[2,3]}],\"c\":{\"d\":null}}",
            "[1.5e999999999999999999]",
            "[-0.0e-0]",
            "{\"é\": 1, \"\\u00e9\": 2}",
        ];
        for text in texts {
            assert_eq!(parse(text).is_ok(), serde_accepts(text), "{text:?}");
        }
        // serde_json's recursion limit: 127 levels pass, 128 do not.
        for depth in [126, 127, 128, 129] {
            let text = "[".repeat(depth) + &"]".repeat(depth);
            assert_eq!(parse(&text).is_ok(), serde_accepts(&text), "depth {depth}");
        }
    }

    /// The serde_json value of a tree (numbers by their text, which serde_json built with
    /// `arbitrary_precision` keeps as written).
    fn to_serde(value: &Value) -> serde_json::Value {
        match value {
            Value::Null => serde_json::Value::Null,
            Value::Bool(b) => serde_json::Value::Bool(*b),
            Value::Number(n) => serde_json::from_str(n.as_str()).unwrap(),
            Value::String(s) => serde_json::Value::String(s.to_string()),
            Value::Array(items) => serde_json::Value::Array(items.iter().map(to_serde).collect()),
            Value::Object(map) => serde_json::Value::Object(
                map.members
                    .iter()
                    .map(|(k, v)| (k.to_string(), to_serde(v)))
                    .collect(),
            ),
        }
    }

    proptest::proptest! {
        /// Texts spliced from JSON's tokens and near misses: accepted exactly when serde_json
        /// accepts them, and then (without a repeated key) read as the same tree.
        #[test]
        fn random_texts_parse_as_serde_json_parses_them(
            tokens in proptest::collection::vec(proptest::sample::select(vec![
                "{", "}", "[", "]", ",", ":", " ", "\n", "\"k\"", "\"a\\\"b\"", "\"\\u00e9\"",
                "\"\\ud800\"", "\"\\q\"", "0", "1", "-", ".", "5", "e", "E", "+", "01", "1.5e-3",
                "true", "false", "null", "tru", "\"", "\\", "\u{1}", "x",
            ]), 0..24),
        ) {
            let text: String = tokens.concat();
            let ours = parse(&text);
            let theirs = serde_json::from_str::<serde_json::Value>(&text);
            proptest::prop_assert_eq!(ours.is_ok(), theirs.is_ok(), "{:?}", text);
            if let (Ok(ours), Ok(theirs)) = (ours, theirs) {
                if ours.repeated_key.is_none() {
                    proptest::prop_assert_eq!(to_serde(&ours.value), theirs, "{:?}", text);
                }
            }
        }
    }

    /// Random JSON values: numbers of the whole grammar, strings of any characters (escaped
    /// when printed), nested arrays and objects.
    fn any_json() -> impl proptest::strategy::Strategy<Value = serde_json::Value> {
        use proptest::prelude::*;
        let leaf = prop_oneof![
            Just(serde_json::Value::Null),
            any::<bool>().prop_map(serde_json::Value::Bool),
            "-?(0|[1-9][0-9]{0,25})(\\.[0-9]{1,12})?([eE][+-]?[0-9]{1,4})?"
                .prop_map(|t| serde_json::from_str(&t).unwrap()),
            any::<String>().prop_map(serde_json::Value::String),
        ];
        leaf.prop_recursive(4, 48, 6, |inner| {
            prop_oneof![
                proptest::collection::vec(inner.clone(), 0..6).prop_map(serde_json::Value::Array),
                proptest::collection::vec((any::<String>(), inner), 0..6)
                    .prop_map(|members| serde_json::Value::Object(members.into_iter().collect())),
            ]
        })
    }

    proptest::proptest! {
        /// Every JSON text serde_json prints, compact or pretty, is read back as its tree.
        #[test]
        fn printed_json_reads_back(value in any_json(), pretty in proptest::prelude::any::<bool>()) {
            let text = if pretty {
                serde_json::to_string_pretty(&value).unwrap()
            } else {
                serde_json::to_string(&value).unwrap()
            };
            let parsed = parse(&text);
            proptest::prop_assert!(parsed.is_ok(), "{:?}", text);
            if let Ok(parsed) = parsed {
                proptest::prop_assert!(parsed.repeated_key.is_none());
                proptest::prop_assert_eq!(to_serde(&parsed.value), value);
            }
        }
    }

    #[test]
    fn numbers_keep_their_text_and_strings_borrow() {
        let parsed = parse("{\"x\": [0.1, -2e-3], \"s\": \"plain\", \"e\": \"a\\tb\"}").unwrap();
        let map = parsed.value.as_object().unwrap();
        let xs = map.get("x").unwrap().as_array().unwrap();
        assert_eq!(xs[0], Value::Number(Number("0.1")));
        assert_eq!(xs[1], Value::Number(Number("-2e-3")));
        assert!(matches!(
            map.get("s"),
            Some(Value::String(Cow::Borrowed("plain")))
        ));
        assert_eq!(map.get("e"), Some(&Value::String("a\tb".into())));
        assert_eq!(map.keys().collect::<Vec<_>>(), ["x", "s", "e"]);
    }

    #[test]
    fn the_first_repeated_key_is_found_in_its_own_object_only() {
        let repeated = |text: &str| parse(text).unwrap().repeated_key.map(|(key, _)| key);
        // Decoded before comparison: an escaped spelling is the same key.
        assert_eq!(repeated(r#"{"a": 1, "\u0061": 2}"#), Some("a".into()));
        assert_eq!(
            repeated(r#"{"x": [1, {"k": 1, "k": 2}]}"#),
            Some("k".into())
        );
        assert_eq!(
            repeated(r#"{"a": {"b": 1, "b": 2}, "a": 3}"#),
            Some("b".into())
        );
        // Equal keys of different objects, and keys spelt inside string values, are not.
        assert_eq!(repeated(r#"[{"a": 1}, {"a": 1}]"#), None);
        assert_eq!(repeated(r#"{"a": {"b": 1}, "b": 2}"#), None);
        assert_eq!(repeated(r#"{"a": "x,\"a\":{", "b": ["a", "a"]}"#), None);
        assert_eq!(repeated(r#"{"a\"": 1, "a": 2}"#), None);
        // Past the linear scan, the hash set finds them too.
        let many: Vec<String> = (0..40).map(|i| format!("\"k{i}\": {i}")).collect();
        let text = format!("{{{}, \"k3\": 0}}", many.join(", "));
        assert_eq!(repeated(&text), Some("k3".into()));
        let parsed = parse("{\n \"a\": 1,\n \"a\": 2}").unwrap();
        assert_eq!(parsed.repeated_key, Some(("a".into(), 15)));
    }
}
