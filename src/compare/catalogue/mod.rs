//! Stage 1, the catalogue: what raylab's picture can be split into. The nodes of the
//! scene's object trees (a channel is per leaf), the known renderer bugs and spot-light
//! bugs, the nodes tried as missing (each with its world without it), and the channel
//! numbering that names one kind of contribution on one leaf.

mod bugs;
mod channels;
mod missing_nodes;
mod nodes;
mod retrace;
mod spot_bugs;

pub use bugs::{ClampBug, NormalBug, Part, ShadowBug, SpawnBug, SpecularBug, local_terms};
pub use channels::{ChannelSpace, Family, Kind};
pub use missing_nodes::{MissingNodes, Slot, TriedNode};
pub use nodes::{MISS, Node, Nodes};
pub use retrace::{trace_again, trace_again_at};
pub use spot_bugs::{SpotBug, SpotWorld, cone_changes, no_falloff_change, spot_worlds};
