//! Import of the legacy COSC342 text scene format. Placeholder until the importer lands.
