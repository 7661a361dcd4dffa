//! The offset registers of the setup: the mill's (D and H read them, as the
//! offset memory type says) and the lathe's (the offset part of T), and
//! their JSON forms (behaviour 1.18, 5.8, 7.13, 7.14, 17.1–17.3).

use std::collections::BTreeMap;

use serde::{Deserialize, Deserializer, Serialize, Serializer};

use super::is_zero;

/// A geometry value and a wear value; their sum is used.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MillPart {
    /// Geometry value.
    pub geometry: f64,
    /// Wear value.
    pub wear: f64,
}

impl MillPart {
    /// Geometry + wear.
    pub fn value(&self) -> f64 {
        self.geometry + self.wear
    }
}

/// One mill register (behaviour 1.18, 17.1). In offset memory A and B the
/// number has one value (A) or one geometry and wear (B), read by H and D
/// alike: `geometry` and `wear`, `d` None. In memory C the H and D tables
/// are apart: `geometry` and `wear` are the H table's, `d` the D table's —
/// None when the setup gives the number one value for both (a register
/// written as a number or `{geometry, wear}`), which is how every document
/// written before memory types reads in every type.
#[derive(Clone, Copy, Debug, Default)]
pub struct MillRegister {
    /// Geometry value (memory C: the H table's).
    pub geometry: f64,
    /// Wear value (memory C: the H table's).
    pub wear: f64,
    /// Memory C: the D table's geometry and wear, when they are not the H
    /// table's.
    pub d: Option<MillPart>,
}

/// Registers are equal when H and D read the same parts: a D part equal to
/// the H part is the same register as none (the form a document writes).
impl PartialEq for MillRegister {
    fn eq(&self, other: &Self) -> bool {
        self.h_part() == other.h_part() && self.d_part() == other.d_part()
    }
}

impl MillRegister {
    /// A register of one geometry and wear for H and D.
    pub fn new(geometry: f64, wear: f64) -> MillRegister {
        MillRegister {
            geometry,
            wear,
            d: None,
        }
    }

    /// The value an H code reads (geometry + wear; memory A's one value).
    pub fn value(&self) -> f64 {
        self.geometry + self.wear
    }

    /// The H table's part (memory A and B: the number's one part).
    pub fn h_part(&self) -> MillPart {
        MillPart {
            geometry: self.geometry,
            wear: self.wear,
        }
    }

    /// The D table's part (memory A and B: the same as H's).
    pub fn d_part(&self) -> MillPart {
        self.d.unwrap_or(self.h_part())
    }

    /// True when H and D read different parts (memory C only).
    pub fn is_split(&self) -> bool {
        self.d.is_some_and(|d| d != self.h_part())
    }

    /// Sets the H part, keeping what D reads.
    pub fn set_h(&mut self, part: MillPart) {
        let d = self.d_part();
        self.geometry = part.geometry;
        self.wear = part.wear;
        self.set_d(d);
    }

    /// Sets the D part, keeping what H reads.
    pub fn set_d(&mut self, part: MillPart) {
        self.d = (part != self.h_part()).then_some(part);
    }
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct MillRegisterFull {
    #[serde(default)]
    geometry: f64,
    #[serde(default)]
    wear: f64,
}

/// Memory C's form: the H and D tables' parts of one number.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct MillRegisterSplit {
    #[serde(default, skip_serializing_if = "is_zero")]
    h: f64,
    #[serde(default, skip_serializing_if = "is_zero")]
    h_wear: f64,
    #[serde(default, skip_serializing_if = "is_zero")]
    d: f64,
    #[serde(default, skip_serializing_if = "is_zero")]
    d_wear: f64,
}

#[derive(Deserialize)]
#[serde(untagged)]
enum MillRegisterForm {
    Value(f64),
    Full(MillRegisterFull),
    Split(MillRegisterSplit),
}

impl Serialize for MillRegister {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        if self.is_split() {
            let d = self.d_part();
            MillRegisterSplit {
                h: self.geometry,
                h_wear: self.wear,
                d: d.geometry,
                d_wear: d.wear,
            }
            .serialize(s)
        } else if self.wear == 0.0 {
            self.geometry.serialize(s)
        } else {
            MillRegisterFull {
                geometry: self.geometry,
                wear: self.wear,
            }
            .serialize(s)
        }
    }
}

impl<'de> Deserialize<'de> for MillRegister {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        match MillRegisterForm::deserialize(d).map_err(|_| {
            serde::de::Error::custom(
                "a mill register is a number, {\"geometry\": …, \"wear\": …}, or in offset memory C {\"h\": …, \"h_wear\": …, \"d\": …, \"d_wear\": …}",
            )
        })? {
            MillRegisterForm::Value(v) => Ok(MillRegister::new(v, 0.0)),
            MillRegisterForm::Full(f) => Ok(MillRegister::new(f.geometry, f.wear)),
            MillRegisterForm::Split(f) => {
                let mut r = MillRegister::new(f.h, f.h_wear);
                r.set_d(MillPart {
                    geometry: f.d,
                    wear: f.d_wear,
                });
                // `{"h": 5}` says D reads 0 even where H and D agree
                // nowhere else: kept apart unless the parts are equal.
                Ok(r)
            }
        }
    }
}

/// One lathe register: X (diameter or radius, see
/// [`super::LatheXOffset`]) and Z, the tool nose radius R, each geometry
/// and wear, and the imaginary tool tip direction T, 0–9 (behaviour 5.8,
/// 17.3).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct LatheRegister {
    /// X geometry.
    pub x: f64,
    /// Z geometry.
    pub z: f64,
    /// X wear.
    #[serde(skip_serializing_if = "is_zero")]
    pub x_wear: f64,
    /// Z wear.
    #[serde(skip_serializing_if = "is_zero")]
    pub z_wear: f64,
    /// Tool nose radius, geometry.
    #[serde(skip_serializing_if = "is_zero")]
    pub r: f64,
    /// Tool nose radius, wear.
    #[serde(skip_serializing_if = "is_zero")]
    pub r_wear: f64,
    /// Imaginary tool tip direction, 0 to 9.
    #[serde(skip_serializing_if = "is_zero_tip")]
    pub t: u8,
}

fn is_zero_tip(t: &u8) -> bool {
    *t == 0
}

/// The largest imaginary tool tip direction (0–9: Fanuc 0i-TF, "Imaginary
/// tool nose"; Haas lathe operator's manual, "Tool tip direction").
pub const MAX_TIP: u8 = 9;

impl LatheRegister {
    /// X value used (geometry + wear), as stored (diameter or radius).
    pub fn x_value(&self) -> f64 {
        self.x + self.x_wear
    }
    /// Z value used (geometry + wear).
    pub fn z_value(&self) -> f64 {
        self.z + self.z_wear
    }
    /// Tool nose radius used (geometry + wear).
    pub fn r_value(&self) -> f64 {
        self.r + self.r_wear
    }
}

/// Register maps are written with two-digit keys, `"01"`, as on the control.
pub(super) mod register_map {
    use super::*;

    pub fn serialize<S: Serializer, T: Serialize>(
        map: &BTreeMap<u16, T>,
        s: S,
    ) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut m = s.serialize_map(Some(map.len()))?;
        for (k, v) in map {
            m.serialize_entry(&format!("{k:02}"), v)?;
        }
        m.end()
    }

    pub fn deserialize<'de, D: Deserializer<'de>, T: Deserialize<'de>>(
        d: D,
    ) -> Result<BTreeMap<u16, T>, D::Error> {
        let raw = BTreeMap::<String, T>::deserialize(d)?;
        let mut out = BTreeMap::new();
        for (k, v) in raw {
            let n = parse_register_number(&k).map_err(serde::de::Error::custom)?;
            if out.insert(n, v).is_some() {
                return Err(serde::de::Error::custom(format!(
                    "register {n:02} is given twice"
                )));
            }
        }
        Ok(out)
    }
}

pub(super) fn parse_register_number(k: &str) -> Result<u16, String> {
    let t = k.trim();
    if t.is_empty() || t.len() > 4 || !t.bytes().all(|b| b.is_ascii_digit()) {
        return Err(format!(
            "register number `{k}` is not a number such as 01 or 12"
        ));
    }
    t.parse::<u16>()
        .map_err(|_| format!("register number `{k}` is not a number"))
}
