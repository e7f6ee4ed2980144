//! A reader of the COSC342 course's text format written from its grammar
//! (`shared/COSC342_FORMAT.md`), independent of raylab's importer: it stands in for
//! the course framework's own reader in the export tests. It checks the block
//! structure, the keywords each block takes and their argument counts, that numbers
//! are whole tokens, that materials are defined before objects name them, and which
//! constructs each framework's dialect has. It reads nothing into a scene.

use std::collections::HashSet;

/// The framework whose reader is checked against.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Framework {
    /// The 2016 framework: point lights only, `Object CSG` nesting, `Mesh PATH`.
    Y2016,
    /// The 2020 framework with its students' extensions: `CSG` and `ObjectGroup`
    /// blocks, Torus, Tube, Octahedron, Opacity, RefractiveIndex, FSAA, sphere lights.
    Y2020,
}

/// Checks `text` as `framework`'s reader reads it: `Err` names the first token it
/// refuses and why.
pub fn check(text: &str, framework: Framework) -> Result<(), String> {
    let tokens = tokens(text);
    let mut reader = Reader {
        tokens,
        at: 0,
        framework,
        materials: HashSet::new(),
    };
    while reader.at < reader.tokens.len() {
        reader.block()?;
    }
    Ok(())
}

/// Tokens with their line, comments (a token starting with `#` to the line's end) left out.
fn tokens(text: &str) -> Vec<(String, usize)> {
    let mut out = Vec::new();
    for (index, line) in text.lines().enumerate() {
        for token in line.split_whitespace() {
            if token.starts_with('#') {
                break;
            }
            out.push((token.to_owned(), index + 1));
        }
    }
    out
}

/// Whether `token` is a number as a whole: sign, digits with at most one point (at least
/// one digit), and an optional exponent.
pub fn is_number(token: &str) -> bool {
    let body = token.strip_prefix(['+', '-']).unwrap_or(token);
    let (mantissa, exponent) = match body.find(['e', 'E']) {
        Some(i) => (&body[..i], Some(&body[i + 1..])),
        None => (body, None),
    };
    let mut parts = mantissa.splitn(2, '.');
    let whole = parts.next().unwrap_or("");
    let fraction = parts.next().unwrap_or("");
    let digits = |s: &str| s.chars().all(|c| c.is_ascii_digit());
    let mantissa_ok =
        digits(whole) && digits(fraction) && !(whole.is_empty() && fraction.is_empty());
    let exponent_ok = exponent.is_none_or(|e| {
        let e = e.strip_prefix(['+', '-']).unwrap_or(e);
        !e.is_empty() && digits(e)
    });
    mantissa_ok && exponent_ok
}

struct Reader {
    tokens: Vec<(String, usize)>,
    at: usize,
    framework: Framework,
    materials: HashSet<String>,
}

impl Reader {
    fn next(&mut self) -> Result<String, String> {
        let token = self
            .tokens
            .get(self.at)
            .map(|(t, _)| t.clone())
            .ok_or_else(|| "unexpected end of file: a block has no `End`".to_owned())?;
        self.at += 1;
        Ok(token)
    }

    fn fail<T>(&self, message: &str) -> Result<T, String> {
        let (token, line) = self
            .tokens
            .get(self.at.saturating_sub(1))
            .cloned()
            .unwrap_or_default();
        Err(format!("line {line}: `{token}`: {message}"))
    }

    fn numbers(&mut self, count: usize) -> Result<Vec<f64>, String> {
        (0..count)
            .map(|_| {
                let token = self.next()?;
                if is_number(&token) {
                    Ok(token.parse::<f64>().expect("a number token parses"))
                } else {
                    self.fail("expected a number (a whole token)")
                }
            })
            .collect()
    }

    fn whole(&mut self) -> Result<(), String> {
        let n = self.numbers(1)?[0];
        if n.fract() == 0.0 && n >= 0.0 {
            Ok(())
        } else {
            self.fail("expected a whole number >= 0")
        }
    }

    fn is_2020(&self) -> bool {
        self.framework == Framework::Y2020
    }

    fn block(&mut self) -> Result<(), String> {
        let word = self.next()?.to_ascii_lowercase();
        match word.as_str() {
            "scene" => self.scene(),
            "camera" => self.camera(),
            "light" => self.light(),
            "material" => self.material(),
            "object" => self.object(false),
            "csg" if self.is_2020() => self.csg_block(),
            "objectgroup" if self.is_2020() => self.group(),
            _ => self.fail("not a block this framework reads"),
        }
    }

    fn scene(&mut self) -> Result<(), String> {
        loop {
            let word = self.next()?.to_ascii_lowercase();
            match word.as_str() {
                "end" => return Ok(()),
                "rendersize" => {
                    self.whole()?;
                    self.whole()?;
                }
                "backgroundcolour" | "ambientlight" => {
                    self.numbers(3)?;
                }
                "raydepth" => self.whole()?,
                "fsaa" if self.is_2020() => self.whole()?,
                "supersampling" if self.is_2020() => {}
                _ => return self.fail("not a Scene keyword of this framework"),
            }
        }
    }

    fn camera(&mut self) -> Result<(), String> {
        if !self.next()?.eq_ignore_ascii_case("PinholeCamera") {
            return self.fail("expected PinholeCamera");
        }
        self.numbers(1)?;
        loop {
            let word = self.next()?;
            if word.eq_ignore_ascii_case("End") {
                return Ok(());
            }
            if !self.transform(&word)? {
                return self.fail("not a Camera keyword");
            }
        }
    }

    /// A transform keyword and its arguments; `false` when `word` is not one.
    fn transform(&mut self, word: &str) -> Result<bool, String> {
        match word.to_ascii_lowercase().as_str() {
            "translate" | "scale3" => {
                self.numbers(3)?;
            }
            "scale" => {
                self.numbers(1)?;
            }
            "rotate" => {
                let axis = self.next()?.to_ascii_uppercase();
                if !["X", "Y", "Z"].contains(&axis.as_str()) {
                    return self.fail("Rotate takes X, Y or Z");
                }
                self.numbers(1)?;
            }
            _ => return Ok(false),
        }
        Ok(true)
    }

    fn light(&mut self) -> Result<(), String> {
        let kind = self.next()?.to_ascii_lowercase();
        let known = if self.is_2020() {
            &[
                "ambientlight",
                "pointlight",
                "directionallight",
                "spotlight",
            ][..]
        } else {
            &["pointlight"][..]
        };
        if !known.contains(&kind.as_str()) {
            return self.fail("not a light type of this framework");
        }
        loop {
            let word = self.next()?.to_ascii_lowercase();
            match word.as_str() {
                "end" => return Ok(()),
                "colour" | "location" | "direction" => {
                    self.numbers(3)?;
                }
                "angle" => {
                    self.numbers(1)?;
                }
                "radius" if self.is_2020() => {
                    self.numbers(1)?;
                }
                "samples" if self.is_2020() => self.whole()?,
                _ => return self.fail("not a Light keyword of this framework"),
            }
        }
    }

    /// A material keyword and its arguments; `false` when `word` is not one.
    fn surface(&mut self, word: &str) -> Result<bool, String> {
        match word.to_ascii_lowercase().as_str() {
            "colour" | "ambient" | "diffuse" | "mirror" => {
                self.numbers(3)?;
            }
            "specular" => {
                self.numbers(4)?;
            }
            "opacity" | "refractiveindex" if self.is_2020() => {
                self.numbers(1)?;
            }
            _ => return Ok(false),
        }
        Ok(true)
    }

    fn material(&mut self) -> Result<(), String> {
        let name = self.next()?;
        loop {
            let word = self.next()?;
            if word.eq_ignore_ascii_case("End") {
                self.materials.insert(name);
                return Ok(());
            }
            if !self.surface(&word)? {
                return self.fail("not a Material keyword of this framework");
            }
        }
    }

    /// After `Object`: its kind and body up to its `End`. `primitive` allows primitives
    /// only (operands of a 2020 CSG block, members of an ObjectGroup).
    fn object(&mut self, primitive: bool) -> Result<(), String> {
        let kind = self.next()?.to_ascii_lowercase();
        match kind.as_str() {
            "sphere" | "plane" | "cube" | "cylinder" | "cone" => {}
            "octahedron" if self.is_2020() => {}
            "torus" | "tube" if self.is_2020() => {
                self.numbers(1)?;
            }
            "mesh" if !self.is_2020() => {
                self.next()?;
            }
            "csg" if !self.is_2020() && !primitive => return self.csg_object(),
            _ => return self.fail("not an object kind this framework reads here"),
        }
        loop {
            let word = self.next()?;
            if word.eq_ignore_ascii_case("End") {
                return Ok(());
            }
            if word.eq_ignore_ascii_case("Material") {
                let name = self.next()?;
                if !self.materials.contains(&name) {
                    return self.fail("material not defined before this object");
                }
            } else if !self.transform(&word)? && !self.surface(&word)? {
                return self.fail("not an Object keyword of this framework");
            }
        }
    }

    /// `Object CSG OP` (2016): two operands at once, then the node's transforms.
    fn csg_object(&mut self) -> Result<(), String> {
        self.operation()?;
        for _ in 0..2 {
            if !self.next()?.eq_ignore_ascii_case("Object") {
                return self.fail("an Object CSG's operands follow it at once");
            }
            self.object(false)?;
        }
        loop {
            let word = self.next()?;
            if word.eq_ignore_ascii_case("End") {
                return Ok(());
            }
            if !self.transform(&word)? {
                return self.fail("not a CSG node keyword");
            }
        }
    }

    fn operation(&mut self) -> Result<(), String> {
        let op = self.next()?.to_ascii_lowercase();
        if ["union", "intersection", "difference"].contains(&op.as_str()) {
            Ok(())
        } else {
            self.fail("CSG takes Union, Intersection or Difference")
        }
    }

    /// `CSG OP` (2020): transforms and exactly two primitive operands, in any order.
    fn csg_block(&mut self) -> Result<(), String> {
        self.operation()?;
        let operands = self.members()?;
        if operands == 2 {
            Ok(())
        } else {
            self.fail("a CSG block takes exactly two operands")
        }
    }

    fn group(&mut self) -> Result<(), String> {
        self.members().map(|_| ())
    }

    /// Transforms and primitive objects up to the `End`; how many objects.
    fn members(&mut self) -> Result<usize, String> {
        let mut count = 0;
        loop {
            let word = self.next()?;
            if word.eq_ignore_ascii_case("End") {
                return Ok(count);
            }
            if word.eq_ignore_ascii_case("Object") {
                self.object(true)?;
                count += 1;
            } else if !self.transform(&word)? {
                return self.fail("not a keyword of this block");
            }
        }
    }
}
