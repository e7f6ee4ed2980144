//! Names for new nodes and materials: the one asked for, or the first free numbered one.

/// `base` if unused, else `base 2`, `base 3`...
#[must_use]
pub fn unique_name<'a>(base: &str, taken: impl Iterator<Item = &'a String>) -> String {
    let taken: Vec<&String> = taken.collect();
    let free = |name: &str| !taken.iter().any(|t| t.as_str() == name);
    if free(base) {
        return base.to_owned();
    }
    (2..)
        .map(|n| format!("{base} {n}"))
        .find(|name| free(name))
        .unwrap_or_else(|| base.to_owned())
}

#[cfg(test)]
mod tests {
    use super::unique_name;

    #[test]
    fn a_taken_name_gets_the_first_free_number() {
        let taken = ["cube".to_owned(), "cube 2".to_owned(), "cube 4".to_owned()];
        assert_eq!(unique_name("sphere", taken.iter()), "sphere");
        assert_eq!(unique_name("cube", taken.iter()), "cube 3");
    }
}
