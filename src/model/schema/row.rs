//! One row of the key table: what a key accepts ([`Allowed`]), what applies when it is absent
//! ([`Fallback`]), where the editor shows it ([`Editor`], [`Group`], [`Widget`]); the builder the section
//! files write their rows with, and the readers validation takes a key's value through.

use super::super::error::{CaseError, Range};
use super::super::file::CaseFile;
use crate::number::csv;
use crate::units::Unit;

/// What values a key accepts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Allowed {
    /// A finite number in an interval.
    Number(Range),
    /// A number in an interval, or a list of them with one entry per pad.
    NumberPerPad(Range),
    /// A number in an interval that must also meet the condition the text states (checked against other
    /// values of the case).
    NumberWhere(Range, &'static str),
    /// A whole number in `[lo, hi]`.
    Integer {
        lo: usize,
        hi: usize,
    },
    /// One of these words (TOML strings).
    Choice(&'static [&'static str]),
    Bool,
    Text,
    /// Depends on other values; the text says how.
    Rule(&'static str),
}

impl Allowed {
    /// The allowed values as one line of text.
    #[must_use]
    pub fn describe(&self) -> String {
        match self {
            Self::Number(r) => r.describe(),
            Self::NumberPerPad(r) => format!("{} (one value, or a list with one per pad)", r.describe()),
            Self::NumberWhere(r, condition) => format!("{}, {condition}", r.describe()),
            Self::Integer { lo, hi } => format!("integer in [{lo}, {hi}]"),
            Self::Choice(words) => words.iter().map(|w| format!("\"{w}\"")).collect::<Vec<_>>().join(" | "),
            Self::Bool => "true | false".into(),
            Self::Text => "text".into(),
            Self::Rule(text) => (*text).to_string(),
        }
    }

    /// The interval of a numeric key.
    #[must_use]
    pub const fn range(&self) -> Option<Range> {
        match *self {
            Self::Number(r) | Self::NumberPerPad(r) | Self::NumberWhere(r, _) => Some(r),
            _ => None,
        }
    }
}

/// What applies when a key is absent (typed: validation and the editor use the value, `tiltpad schema`
/// prints it). `F` is the file the key belongs to (a case file, a rotor file).
pub enum Fallback<F: 'static = CaseFile> {
    /// The key must be given.
    Required,
    /// This number, in the key's unit.
    Number(f64),
    /// This number, in the key's unit: a convention of common practice, not a property (design limits).
    Convention(f64),
    /// This whole number.
    Count(usize),
    /// This word (a choice).
    Word(&'static str),
    Flag(bool),
    /// Empty text.
    Empty,
    /// Another value of the case: `text` names it, `value` computes it from the file (in the key's unit).
    Follows {
        text: &'static str,
        value: fn(&F) -> f64,
    },
    /// `value` where `text` says (fixed sectors); elsewhere the key is required.
    Sometimes {
        value: f64,
        text: &'static str,
    },
    /// Not one value: the absence means something (a rigid pivot, a temperature from the solve), or one of
    /// several keys must be given; the text says what.
    Rule(&'static str),
}

/// Where and how the workbench's editor shows a key.
pub struct Editor<F: 'static = CaseFile> {
    pub group: Group,
    /// The row's label (its tooltip is the row's meaning).
    pub label: &'static str,
    pub widget: Widget,
    /// Whether the row applies to this file (thermal rows only with the thermal model, …).
    pub when: fn(&F) -> bool,
}

/// The editor's groups, in order: as an engineer thinks about a bearing.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Group {
    /// The case's title, above the groups.
    Title,
    Geometry,
    Pads,
    Orifices,
    Lubricant,
    Operating,
    Physics,
    Thermal,
    Fidelity,
    Hydraulics,
    Limits,
}

impl Group {
    /// The groups under headers, in order.
    pub const SECTIONS: [Self; 10] = [
        Self::Geometry,
        Self::Pads,
        Self::Orifices,
        Self::Lubricant,
        Self::Operating,
        Self::Physics,
        Self::Thermal,
        Self::Fidelity,
        Self::Hydraulics,
        Self::Limits,
    ];

    /// The header's text.
    #[must_use]
    pub const fn title(self) -> &'static str {
        match self {
            Self::Title => "Title",
            Self::Geometry => "Geometry",
            Self::Pads => "Pads",
            Self::Orifices => "Orifices",
            Self::Lubricant => "Lubricant",
            Self::Operating => "Operating point",
            Self::Physics => "Physics model",
            Self::Thermal => "Thermal model",
            Self::Fidelity => "Fidelity",
            Self::Hydraulics => "Hydraulics (controllable bearing)",
            Self::Limits => "Design limits",
        }
    }

    /// Open when the workbench starts.
    #[must_use]
    pub const fn open(self) -> bool {
        matches!(self, Self::Title | Self::Geometry | Self::Pads | Self::Operating)
    }
}

/// How the editor edits a key.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Widget {
    /// A number always shown (its value, or the default, or 0 while absent), with this many decimals.
    Number(usize),
    /// A number with a checkbox: unchecked, the key is absent and the default applies.
    Optional(usize),
    /// A choice among the row's words, shown with these labels (one per word of [`Allowed::Choice`]).
    Choice(&'static [&'static str]),
    /// A line of text; empty removes the key.
    Text,
    /// Drawn by the editor's own code for this key (lists per pad, arrays of tables, choices that change
    /// other keys).
    Custom,
}

/// One case key (or rotor-file key, `F` = the rotor file).
pub struct KeySpec<F: 'static = CaseFile> {
    /// Dotted key as written in the case file and in `--set`.
    pub key: &'static str,
    /// Unit of the value as written (engineering units; `–` dimensionless, empty for counts and words).
    pub unit: &'static str,
    /// The SI value of one of `unit` (from its [`Unit`]).
    pub si: f64,
    pub allowed: Allowed,
    /// Range of values engineers usually use (sets the editor's drag speed; a sensible sweep range).
    pub typical: Option<(f64, f64)>,
    /// What applies when the key is absent.
    pub default: Fallback<F>,
    /// What the value does physically.
    pub meaning: &'static str,
    /// The key's row in the workbench's editor; `None`: not edited there.
    pub editor: Option<Editor<F>>,
    /// A tuning key: a number the solver reads through its row ([`crate::model::tuning`]), with no field of
    /// its own in the file or the SI case.
    pub tuning: bool,
}

// Every field is Copy whatever the file type (the functions take it by reference).
impl<F> Clone for Fallback<F> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<F> Copy for Fallback<F> {}
impl<F> Clone for Editor<F> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<F> Copy for Editor<F> {}
impl<F> Clone for KeySpec<F> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<F> Copy for KeySpec<F> {}

impl<F> std::fmt::Debug for KeySpec<F> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("KeySpec")
            .field("key", &self.key)
            .field("unit", &self.unit)
            .field("allowed", &self.allowed)
            .finish()
    }
}

const fn always<F>(_: &F) -> bool {
    true
}

// ------------------------------------------------------------------------------------- building a row

impl<F> KeySpec<F> {
    const fn new(key: &'static str, unit: Unit, allowed: Allowed) -> Self {
        Self {
            key,
            unit: unit.symbol,
            si: unit.si,
            allowed,
            typical: None,
            default: Fallback::Required,
            meaning: "",
            editor: None,
            tuning: false,
        }
    }

    /// A number in `range`, written in `unit`.
    pub const fn number(key: &'static str, unit: Unit, range: Range) -> Self {
        Self::new(key, unit, Allowed::Number(range))
    }
    /// A number in `range`, or one per pad.
    pub const fn per_pad(key: &'static str, unit: Unit, range: Range) -> Self {
        Self::new(key, unit, Allowed::NumberPerPad(range))
    }
    /// A number in `range` that also meets `condition` (checked against other values).
    pub const fn number_where(key: &'static str, unit: Unit, range: Range, condition: &'static str) -> Self {
        Self::new(key, unit, Allowed::NumberWhere(range, condition))
    }
    /// A number whose allowed values depend on others (`rule` says how).
    pub const fn rule(key: &'static str, unit: Unit, rule: &'static str) -> Self {
        Self::new(key, unit, Allowed::Rule(rule))
    }
    /// A whole number in `[lo, hi]`.
    pub const fn integer(key: &'static str, unit: Unit, lo: usize, hi: usize) -> Self {
        Self::new(key, unit, Allowed::Integer { lo, hi })
    }
    /// One of `words`.
    pub const fn choice(key: &'static str, words: &'static [&'static str]) -> Self {
        Self::new(key, crate::units::COUNT, Allowed::Choice(words))
    }
    /// `true` or `false`.
    pub const fn flag(key: &'static str) -> Self {
        Self::new(key, crate::units::COUNT, Allowed::Bool)
    }
    /// Free text.
    pub const fn text(key: &'static str) -> Self {
        Self { default: Fallback::Empty, ..Self::new(key, crate::units::COUNT, Allowed::Text) }
    }

    /// The values engineers usually use.
    pub const fn typical(self, lo: f64, hi: f64) -> Self {
        Self { typical: Some((lo, hi)), ..self }
    }
    /// What applies when the key is absent.
    pub const fn default(self, default: Fallback<F>) -> Self {
        Self { default, ..self }
    }
    /// A number that applies when the key is absent (in the key's unit).
    pub const fn or(self, value: f64) -> Self {
        self.default(Fallback::Number(value))
    }
    /// What the value does physically.
    pub const fn meaning(self, meaning: &'static str) -> Self {
        Self { meaning, ..self }
    }
    /// The key's row in the editor: its group, label and widget.
    pub const fn edit(self, group: Group, label: &'static str, widget: Widget) -> Self {
        Self { editor: Some(Editor { group, label, widget, when: always }), ..self }
    }
    /// A tuning key: the solver reads the value through this row (`case.tuning.value(key!("…"))`), so the key
    /// needs no field in the file or the SI case ([`crate::model::tuning`]).
    pub const fn tuning(self) -> Self {
        Self { tuning: true, ..self }
    }
    /// The editor shows the row only for files where `when` holds.
    pub const fn when(self, when: fn(&F) -> bool) -> Self {
        match self.editor {
            Some(e) => Self { editor: Some(Editor { when, ..e }), ..self },
            None => self,
        }
    }
}

// ----------------------------------------------------------------------------------- reading a value

impl<F> KeySpec<F> {
    /// A value in the key's unit, in SI.
    #[must_use]
    pub fn to_si(&self, value: f64) -> f64 {
        value * self.si
    }

    /// An SI value, in the key's unit.
    #[must_use]
    pub fn from_si(&self, value_si: f64) -> f64 {
        value_si / self.si
    }

    /// The number that applies when the key is absent, in the key's unit (a fixed one: not a rule, not
    /// another key's value).
    #[must_use]
    #[allow(clippy::cast_precision_loss)]
    pub fn default_number(&self) -> Option<f64> {
        match self.default {
            Fallback::Number(v) | Fallback::Convention(v) | Fallback::Sometimes { value: v, .. } => Some(v),
            Fallback::Count(n) => Some(n as f64),
            _ => None,
        }
    }

    /// The number that applies to `file` when the key is absent, in the key's unit (fixed, or another value
    /// of the file).
    #[must_use]
    pub fn default_in(&self, file: &F) -> Option<f64> {
        match self.default {
            Fallback::Follows { value, .. } => Some(value(file)),
            _ => self.default_number(),
        }
    }

    /// `value` as written at `key` (the row's key, or an indexed form of it), checked against the row's
    /// interval.
    ///
    /// # Errors
    /// [`CaseError::OutOfRange`] naming `key`, the value and the interval.
    pub fn check(&self, key: &str, value: f64) -> Result<f64, CaseError> {
        match self.allowed.range() {
            Some(r) => r.check(key, value),
            None => Ok(value),
        }
    }

    /// The key's number in SI: the value given (checked), else the row's default.
    ///
    /// # Errors
    /// A value outside the row's interval; an absent key without a fixed default
    /// ([`CaseError::MissingKey`]).
    pub fn value(&self, given: Option<f64>) -> Result<f64, CaseError> {
        self.value_at(self.key, given)
    }

    /// [`Self::value`] for the key written as `key` (an indexed form of the row's key:
    /// `bearing.pad.2.offset`, `operating.injection_pressure_bar[1]`), which errors name.
    ///
    /// # Errors
    /// As [`Self::value`].
    pub fn value_at(&self, key: &str, given: Option<f64>) -> Result<f64, CaseError> {
        match given {
            Some(v) => Ok(self.to_si(self.check(key, v)?)),
            None => self.default_number().map(|v| self.to_si(v)).ok_or_else(|| self.missing()),
        }
    }

    /// The key's number in SI for `file`: the value given (checked), else the row's default, which may be
    /// another value of the file (not checked again: it is that value's row that checks it).
    ///
    /// # Errors
    /// A value outside the row's interval; an absent key without a default.
    pub fn value_in(&self, file: &F, given: Option<f64>) -> Result<f64, CaseError> {
        match given {
            Some(v) => self.value(Some(v)),
            None => self.default_in(file).map(|v| self.to_si(v)).ok_or_else(|| self.missing()),
        }
    }

    /// The key's whole number for `file`: the value given, else the row's default (a fixed count, or one
    /// that follows other values of the file), checked against `[lo, hi]` either way.
    ///
    /// # Errors
    /// A value outside `[lo, hi]`, naming the key; an absent key without a default.
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    pub fn count_in(&self, file: &F, given: Option<usize>) -> Result<usize, CaseError> {
        match (given, self.default) {
            (None, Fallback::Follows { value, .. }) => self.count(Some(value(file).round().max(0.0) as usize)),
            _ => self.count(given),
        }
    }

    /// An optional number in SI: `None` when absent, else the value checked.
    ///
    /// # Errors
    /// A value outside the row's interval.
    pub fn optional(&self, given: Option<f64>) -> Result<Option<f64>, CaseError> {
        given.map(|v| self.value(Some(v))).transpose()
    }

    /// The key's whole number: the value given (checked against `[lo, hi]`), else `fallback` (`None`: the
    /// row's default).
    ///
    /// # Errors
    /// A value outside `[lo, hi]`, naming the key; an absent key without a default.
    pub fn count(&self, given: Option<usize>) -> Result<usize, CaseError> {
        self.count_at(self.key, given)
    }

    /// [`Self::count`] for an indexed form `key` of the row's key.
    ///
    /// # Errors
    /// As [`Self::count`].
    pub fn count_at(&self, key: &str, given: Option<usize>) -> Result<usize, CaseError> {
        let value = match (given, self.default) {
            (Some(v), _) | (None, Fallback::Count(v)) => v,
            _ => return Err(self.missing()),
        };
        if let Allowed::Integer { lo, hi } = self.allowed {
            if !(lo..=hi).contains(&value) {
                #[allow(clippy::cast_precision_loss)]
                return Err(CaseError::OutOfRange {
                    key: key.to_string(),
                    value: value as f64,
                    allowed: format!("an {}", self.allowed.describe()),
                });
            }
        }
        Ok(value)
    }

    fn missing(&self) -> CaseError {
        CaseError::missing(self.key, self.meaning.split(['.', ':']).next().unwrap_or(self.meaning))
    }

    /// The default as `tiltpad schema` writes it (empty for a required key).
    #[must_use]
    pub fn default_text(&self) -> String {
        match self.default {
            Fallback::Required => String::new(),
            Fallback::Number(v) => csv(v),
            Fallback::Convention(v) => format!("{} (convention)", csv(v)),
            Fallback::Count(n) => n.to_string(),
            Fallback::Word(w) => w.to_string(),
            Fallback::Flag(b) => b.to_string(),
            Fallback::Empty => "empty".into(),
            Fallback::Follows { text, .. } | Fallback::Sometimes { text, .. } | Fallback::Rule(text) => text.into(),
        }
    }
}
