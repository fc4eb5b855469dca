//! The two declaration macros: `settings!` for a settings struct, `choice!` for the enum of
//! a setting that takes one of several names.

/// Declares a settings struct, one line per field: its doc (first line: the short help), type,
/// default and declaration (`flag`, `symbol`, `quantity`, `unit`, `check`, `value_name`; any
/// field of [`crate::settings::Decl`]).
///
/// Generates the struct (`serde(default, deny_unknown_fields)`, the default in each field's
/// rustdoc), `Default`, [`crate::settings::Declared`] and the methods `check_declared` (every
/// field against its declared range), `real` and `set_real` (a field as a number, by key).
///
/// The `aliases NAME { .. }` form declares names that are no field of a settings struct, as the
/// constant `NAME: &[Decl]`: an alias that sets several fields (`mu = 0.4, sets: &["mu_ground",
/// "mu_palm"], ..`), or a command's own flag and the key its messages name (`runs, flag:
/// Some("runs")`), so that every flag a message names comes from a declaration.
macro_rules! settings {
    (
        $(#[doc = $sdoc:literal])*
        section = $section:literal;
        aliases $name:ident {
            $(
                $(#[doc = $doc:literal])*
                $key:ident $(= $default:expr)? $(, $k:ident : $v:expr)* ;
            )*
        }
    ) => {
        $(#[doc = $sdoc])*
        pub(crate) const $name: &[$crate::settings::decl::Decl] = &[$(
            $crate::settings::decl::Decl {
                key: stringify!($key),
                section: $section,
                doc: concat!($($doc, "\n"),*),
                $(default: || $crate::settings::decl::Value::text(&$default),)?
                $($k: $v,)*
                ..$crate::settings::decl::Decl::BASE
            },
        )*];
    };
    (
        $(#[doc = $sdoc:literal])*
        section = $section:literal;
        pub struct $name:ident {
            $(
                $(#[doc = $doc:literal])*
                $field:ident : $ty:ty = $default:expr $(, $k:ident : $v:expr)* ;
            )*
        }
    ) => {
        $(#[doc = $sdoc])*
        #[doc = concat!("\n\nTOML section `[", $section, "]`.")]
        #[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
        #[serde(default, deny_unknown_fields)]
        pub struct $name {
            $(
                $(#[doc = $doc])*
                #[doc = concat!("\n\nDefault: `", stringify!($default), "`.")]
                pub $field: $ty,
            )*
        }

        impl Default for $name {
            fn default() -> Self {
                $name { $($field: $default,)* }
            }
        }

        impl $crate::settings::decl::Declared for $name {
            const DECLS: &'static [$crate::settings::decl::Decl] = &[$(
                $crate::settings::decl::Decl {
                    key: stringify!($field),
                    section: $section,
                    doc: concat!($($doc, "\n"),*),
                    kind: <$ty as $crate::settings::decl::Value>::KIND,
                    default: || {
                        $crate::settings::decl::Value::text(&<$name as Default>::default().$field)
                    },
                    $($k: $v,)*
                    ..$crate::settings::decl::Decl::BASE
                },
            )*];
        }

        impl $crate::settings::decl::Numbers for $name {
            fn real(&self, key: &str) -> Option<f64> {
                $name::real(self, key)
            }
            fn set_real(&mut self, key: &str, v: f64) -> bool {
                $name::set_real(self, key, v)
            }
        }

        #[allow(dead_code)]
        impl $name {
            /// Checks every field against its declared range; the error names the key and
            /// the value.
            pub(crate) fn check_declared(&self) -> $crate::error::Result<()> {
                let mut decls = <Self as $crate::settings::decl::Declared>::DECLS.iter();
                $(
                    $crate::settings::decl::Value::check(
                        &self.$field,
                        decls.next().expect("one declaration per field"),
                    )?;
                )*
                Ok(())
            }

            /// The field `key` as a number, where it is one.
            pub(crate) fn real(&self, key: &str) -> Option<f64> {
                match key {
                    $(stringify!($field) => $crate::settings::decl::Value::real(&self.$field),)*
                    _ => None,
                }
            }

            /// Sets the field `key` from a number; false where it is not one.
            pub(crate) fn set_real(&mut self, key: &str, v: f64) -> bool {
                match key {
                    $(stringify!($field) => {
                        $crate::settings::decl::Value::set_real(&mut self.$field, v)
                    })*
                    _ => false,
                }
            }

            /// [`Self::set_real`] of `key` looked up once: the setter a loop over many values
            /// calls without matching the name each time.
            pub(crate) fn real_setter(key: &str) -> Option<fn(&mut Self, f64) -> bool> {
                match key {
                    $(stringify!($field) => Some(|s: &mut Self, v: f64| {
                        $crate::settings::decl::Value::set_real(&mut s.$field, v)
                    }),)*
                    _ => None,
                }
            }
        }
    };
}

/// The long flag declared for `key` in the aliases `decls`, for a clap attribute: `#[arg(long =
/// flag!(ACCURACY_FLAGS, runs))]`. A key without a declared flag fails the build.
macro_rules! flag {
    ($decls:expr, $key:ident) => {
        const { $crate::settings::decl::flag_of($decls, stringify!($key)) }
    };
}

/// Declares the enum of a setting that takes one of several names: each variant with its doc
/// and its one spelling, used by serde, clap, `as_str`, `Display` and `FromStr` alike.
macro_rules! choice {
    (
        $(#[doc = $doc:literal])*
        pub enum $name:ident {
            $( $(#[doc = $vdoc:literal])* $variant:ident = $text:literal, )*
        }
    ) => {
        $(#[doc = $doc])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
        pub enum $name {
            $( $(#[doc = $vdoc])* #[serde(rename = $text)] $variant, )*
        }

        #[allow(dead_code)]
        impl $name {
            /// Every value, in declaration order.
            pub const ALL: &'static [$name] = &[$($name::$variant),*];
            /// Every spelling, in declaration order.
            pub const NAMES: &'static [&'static str] = &[$($text),*];

            /// The one spelling (TOML, JSON, flags).
            pub fn as_str(self) -> &'static str {
                match self {
                    $($name::$variant => $text,)*
                }
            }

            /// The value's index in [`Self::ALL`] and [`Self::NAMES`].
            pub fn index(self) -> u8 {
                self as u8
            }
        }

        impl std::fmt::Display for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str(self.as_str())
            }
        }

        impl std::str::FromStr for $name {
            type Err = String;
            fn from_str(s: &str) -> std::result::Result<Self, String> {
                Self::ALL.iter().copied().find(|v| v.as_str() == s).ok_or_else(|| {
                    format!("'{s}' is not one of {}", Self::NAMES.join(", "))
                })
            }
        }

        impl $crate::settings::decl::Value for $name {
            const KIND: $crate::settings::decl::Kind = $crate::settings::decl::Kind::Choice(Self::NAMES);
            fn text(&self) -> String {
                self.as_str().to_string()
            }
        }

        impl clap::ValueEnum for $name {
            fn value_variants<'a>() -> &'a [Self] {
                Self::ALL
            }
            fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
                let help = match self {
                    $($name::$variant => concat!($($vdoc),*),)*
                };
                let first = help.trim().split(". ").next().unwrap_or("").trim_end_matches('.');
                Some(clap::builder::PossibleValue::new(self.as_str()).help(first.to_string()))
            }
        }
    };
}
