//! The offset registers of the setup: the mill's (D and H read them) and
//! the lathe's (the offset part of T), their JSON forms, and the register
//! specs of `--offset` (behaviour 1.18, 5.8, 7.13, 7.14).

use std::collections::BTreeMap;

use serde::{Deserialize, Deserializer, Serialize, Serializer};

use super::{MachineKind, Setup, is_zero};

/// One mill register: geometry + wear; their sum is used (behaviour 1.18).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MillRegister {
    /// Geometry value.
    pub geometry: f64,
    /// Wear value.
    pub wear: f64,
}

impl MillRegister {
    /// The value a D or H code reads.
    pub fn value(&self) -> f64 {
        self.geometry + self.wear
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

#[derive(Deserialize)]
#[serde(untagged)]
enum MillRegisterForm {
    Value(f64),
    Full(MillRegisterFull),
}

impl Serialize for MillRegister {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        if self.wear == 0.0 {
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
                "a mill register is a number or {\"geometry\": …, \"wear\": …}",
            )
        })? {
            MillRegisterForm::Value(v) => Ok(MillRegister {
                geometry: v,
                wear: 0.0,
            }),
            MillRegisterForm::Full(f) => Ok(MillRegister {
                geometry: f.geometry,
                wear: f.wear,
            }),
        }
    }
}

/// One lathe register: X (diameter or radius, see [`LatheXOffset`]) and Z,
/// each geometry + wear (behaviour 5).
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
}

impl LatheRegister {
    /// X value used (geometry + wear), as stored (diameter or radius).
    pub fn x_value(&self) -> f64 {
        self.x + self.x_wear
    }
    /// Z value used (geometry + wear).
    pub fn z_value(&self) -> f64 {
        self.z + self.z_wear
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

impl Setup {
    /// Sets one register from a command-line style spec: mill `NN=VALUE`
    /// (`01=5.0`, `1=-2.5`), lathe `NN=X<v>,Z<v>` (`08=X0.4,Z-0.2`).
    /// Wear can follow as `W<v>` (mill) or `XW<v>`/`ZW<v>` (lathe).
    pub fn set_register(&mut self, spec: &str) -> Result<(), String> {
        let (num, value) = spec
            .split_once('=')
            .ok_or_else(|| format!("offset `{spec}`: expected NN=VALUE"))?;
        let n = parse_register_number(num).map_err(|e| format!("offset `{spec}`: {e}"))?;
        let number = |t: &str| -> Result<f64, String> {
            let t = t.trim();
            t.parse::<f64>()
                .ok()
                .filter(|v| v.is_finite() && !t.is_empty())
                .ok_or_else(|| format!("offset `{spec}`: `{t}` is not a number"))
        };
        match self.machine {
            MachineKind::Mill => {
                let mut reg = MillRegister::default();
                for (i, part) in value.split(',').enumerate() {
                    let p = part.trim();
                    let upper = p.to_ascii_uppercase();
                    if let Some(w) = upper.strip_prefix('W') {
                        reg.wear = number(w)?;
                    } else if i == 0 {
                        reg.geometry = number(upper.strip_prefix('G').unwrap_or(&upper))?;
                    } else {
                        return Err(format!(
                            "offset `{spec}`: mill registers are NN=VALUE or NN=VALUE,W<wear>"
                        ));
                    }
                }
                self.offsets.insert(n, reg);
            }
            MachineKind::Lathe => {
                let mut reg = LatheRegister::default();
                for part in value.split(',') {
                    let p = part.trim().to_ascii_uppercase();
                    if let Some(v) = p.strip_prefix("XW") {
                        reg.x_wear = number(v)?;
                    } else if let Some(v) = p.strip_prefix("ZW") {
                        reg.z_wear = number(v)?;
                    } else if let Some(v) = p.strip_prefix('X') {
                        reg.x = number(v)?;
                    } else if let Some(v) = p.strip_prefix('Z') {
                        reg.z = number(v)?;
                    } else {
                        return Err(format!(
                            "offset `{spec}`: lathe registers are NN=X<v>,Z<v> (wear: XW<v>, ZW<v>)"
                        ));
                    }
                }
                self.lathe_offsets.insert(n, reg);
            }
        }
        Ok(())
    }
}
