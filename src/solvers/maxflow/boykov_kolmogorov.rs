//! The three stages of the Boykov-Kolmogorov max-flow algorithm (PAMI 2004), written from the
//! paper's description:
//!
//! 1. **growth**: active nodes of the source tree `S` and the sink tree `T` take free neighbours
//!    over non-saturated arcs, until an arc joins the two trees (an augmenting path);
//! 2. **augmentation**: the bottleneck flow is pushed along the path; arcs that saturate cut their
//!    child off its tree, and that child becomes an *orphan*;
//! 3. **adoption**: each orphan looks for a new parent in its own tree that still leads to the
//!    terminal; if there is none it becomes free and its children become orphans in turn.
//!
//! The trees are never rebuilt from scratch, which is what makes the algorithm fast on the short
//! paths of grid graphs. Two refinements from the paper keep the paths short: a node's distance to
//! its terminal is remembered with a timestamp, so an orphan prefers the closest valid parent, and
//! growth re-parents a node when it finds a shorter route to the root.
//!
//! Nothing here allocates: the queues are kept in [`Residual`] and only grow to the node count.

use super::residual::{Arc, NO_PARENT, ORPHAN, Residual, TERMINAL};
use crate::core::math::lesser;

/// Marks an origin search that hit an orphan: the neighbour does not lead to the terminal.
const UNREACHABLE: u32 = u32::MAX;

impl Residual {
    /// Runs the algorithm to the end on a network made by [`Residual::build`] and returns the flow
    /// pushed along augmenting paths (not counting the flow `build` pushed straight through).
    pub fn solve(&mut self) -> f64 {
        let mut flow = 0.0f64;
        // The node being grown is kept after an augmentation: it usually has more free neighbours
        // to take, and starting again from the queue would lose that locality.
        let mut current: Option<u32> = None;
        loop {
            let node = match current.take() {
                Some(node) if self.nodes[node as usize].parent != NO_PARENT => {
                    self.nodes[node as usize].queued = false;
                    node
                }
                Some(node) => {
                    self.nodes[node as usize].queued = false;
                    match self.next_active() {
                        Some(node) => node,
                        None => break,
                    }
                }
                None => match self.next_active() {
                    Some(node) => node,
                    None => break,
                },
            };
            let joining_arc = self.grow(node);
            self.time += 1;
            if let Some(arc) = joining_arc {
                // Still counts as queued, so adoption does not queue it a second time.
                self.nodes[node as usize].queued = true;
                current = Some(node);
                flow += f64::from(self.augment(arc));
                self.adopt_orphans();
            }
        }
        flow
    }

    /// Takes the next node of the active queue that is still in a tree.
    fn next_active(&mut self) -> Option<u32> {
        while let Some(node) = self.active.pop_front() {
            let state = &mut self.nodes[node as usize];
            state.queued = false;
            if state.parent != NO_PARENT {
                return Some(node);
            }
        }
        None
    }

    fn set_active(&mut self, node: u32) {
        let state = &mut self.nodes[node as usize];
        if !state.queued {
            state.queued = true;
            self.active.push_back(node);
        }
    }

    /// Growth from one active node. Returns the arc from the source tree to the sink tree that
    /// closes an augmenting path, if one is met.
    fn grow(&mut self, node: u32) -> Option<u32> {
        let from = self.nodes[node as usize];
        for arc_index in self.arcs_of(node) {
            let arc = self.arcs[arc_index];
            // Residual capacity in the direction away from the tree's terminal: out of the node
            // for the source tree, into it for the sink tree.
            let open = if from.in_sink_tree {
                self.arcs[arc.sister as usize].residual
            } else {
                arc.residual
            };
            if open <= 0.0 {
                continue;
            }
            // The arc flow would take between the two: away from the source tree's root, towards
            // the sink tree's.
            let flow_arc = if from.in_sink_tree {
                arc.sister
            } else {
                arc_index as u32
            };
            let neighbour = &mut self.nodes[arc.head as usize];
            if neighbour.parent == NO_PARENT {
                neighbour.in_sink_tree = from.in_sink_tree;
                neighbour.parent = flow_arc;
                neighbour.parent_node = node;
                neighbour.timestamp = from.timestamp;
                neighbour.distance = from.distance + 1;
                self.set_active(arc.head);
            } else if neighbour.in_sink_tree != from.in_sink_tree {
                return Some(flow_arc);
            } else if neighbour.timestamp <= from.timestamp && neighbour.distance > from.distance {
                // A shorter route to the root through `node`: shorter paths mean cheaper
                // augmentations and adoptions later.
                neighbour.parent = flow_arc;
                neighbour.parent_node = node;
                neighbour.timestamp = from.timestamp;
                neighbour.distance = from.distance + 1;
            }
        }
        None
    }

    /// Pushes the bottleneck flow along the path source root -> ... -> `joining_arc` -> ... -> sink
    /// root, and makes orphans of the nodes whose parent arc saturates. Returns the flow pushed.
    fn augment(&mut self, joining_arc: u32) -> f32 {
        let joining = self.arcs[joining_arc as usize];
        let source_end = self.arcs[joining.sister as usize].head;
        let sink_end = joining.head;

        // The first walk finds the bottleneck and keeps the path's (node, parent arc) pairs, so
        // the second walk, which pushes the flow, reads them in order instead of following
        // parents again (each step of a walk waits for the load of the step before).
        let mut path = std::mem::take(&mut self.path);
        path.clear();
        let mut bottleneck = joining.residual;
        // Source half: flow runs from each parent down to its child.
        let mut node = source_end;
        loop {
            let state = self.nodes[node as usize];
            if state.parent == TERMINAL {
                break;
            }
            path.push((node, state.parent));
            bottleneck = lesser(bottleneck, self.arcs[state.parent as usize].residual);
            node = state.parent_node;
        }
        let source_root = node;
        let source_half = path.len();
        bottleneck = lesser(bottleneck, self.nodes[node as usize].terminal);
        // Sink half: flow runs from each child up to its parent.
        let mut node = sink_end;
        loop {
            let state = self.nodes[node as usize];
            if state.parent == TERMINAL {
                break;
            }
            path.push((node, state.parent));
            bottleneck = lesser(bottleneck, self.arcs[state.parent as usize].residual);
            node = state.parent_node;
        }
        let sink_root = node;
        bottleneck = lesser(bottleneck, -self.nodes[node as usize].terminal);

        self.push(joining_arc, bottleneck);
        // The bottleneck is the minimum of these residuals, so `x - bottleneck` is exactly zero for
        // the arc that set it and positive for the others: saturation tests need no tolerance.
        // Orphans are made in path order, each half from its joining end to its root.
        for (k, &(node, arc)) in path.iter().enumerate() {
            if k == source_half {
                self.settle_root(source_root, -bottleneck);
            }
            self.push(arc, bottleneck);
            if self.arcs[arc as usize].residual == 0.0 {
                self.make_orphan_front(node);
            }
        }
        if source_half == path.len() {
            self.settle_root(source_root, -bottleneck);
        }
        self.settle_root(sink_root, bottleneck);
        self.path = path;
        bottleneck
    }

    /// Takes an augmentation's flow off a root's terminal arc (`change` is negative for the
    /// source's, positive for the sink's); a root whose arc saturates becomes an orphan.
    fn settle_root(&mut self, root: u32, change: f32) {
        let state = &mut self.nodes[root as usize];
        state.terminal += change;
        if state.terminal == 0.0 {
            self.make_orphan_front(root);
        }
    }

    #[inline]
    fn push(&mut self, arc: u32, amount: f32) {
        let sister = self.arcs[arc as usize].sister;
        self.arcs[arc as usize].residual -= amount;
        self.arcs[sister as usize].residual += amount;
    }

    /// Orphans made by an augmentation go first: they are near the path just augmented, where the
    /// trees changed, and settling them first keeps the walk local.
    fn make_orphan_front(&mut self, node: u32) {
        self.nodes[node as usize].parent = ORPHAN;
        self.orphans.push_front(node);
    }

    fn make_orphan_back(&mut self, node: u32) {
        self.nodes[node as usize].parent = ORPHAN;
        self.orphans.push_back(node);
    }

    fn adopt_orphans(&mut self) {
        while let Some(orphan) = self.orphans.pop_front() {
            self.adopt(orphan);
        }
    }

    /// Finds the orphan a new parent in its own tree whose path to the terminal is intact, the
    /// closest one if several; otherwise frees it and orphans its children.
    fn adopt(&mut self, orphan: u32) {
        let in_sink_tree = self.nodes[orphan as usize].in_sink_tree;
        let mut best: Option<(u32, u32)> = None; // (arc, distance of the parent)
        for arc_index in self.arcs_of(orphan) {
            let arc = self.arcs[arc_index];
            // The new parent must be able to send flow to the orphan (source tree) or receive
            // flow from it (sink tree).
            let open = if in_sink_tree {
                arc.residual
            } else {
                self.arcs[arc.sister as usize].residual
            };
            if open <= 0.0 {
                continue;
            }
            let candidate = self.nodes[arc.head as usize];
            if candidate.parent == NO_PARENT || candidate.in_sink_tree != in_sink_tree {
                continue;
            }
            let distance = self.distance_to_terminal(arc.head);
            if distance == UNREACHABLE {
                continue;
            }
            if best.is_none_or(|(_, d)| distance < d) {
                best = Some((arc_index as u32, distance));
            }
            self.stamp_path(arc.head, distance);
        }

        if let Some((arc, distance)) = best {
            let Arc { head, sister, .. } = self.arcs[arc as usize];
            let state = &mut self.nodes[orphan as usize];
            state.parent = if in_sink_tree { arc } else { sister };
            state.parent_node = head;
            state.timestamp = self.time;
            state.distance = distance + 1;
            return;
        }

        // No parent: the orphan becomes free. Its neighbours in the same tree that could reach it
        // become active (to take it back later if a path opens), and its children become orphans.
        self.nodes[orphan as usize].timestamp = 0;
        for arc_index in self.arcs_of(orphan) {
            let arc = self.arcs[arc_index];
            let neighbour = self.nodes[arc.head as usize];
            if neighbour.parent == NO_PARENT || neighbour.in_sink_tree != in_sink_tree {
                continue;
            }
            let open = if in_sink_tree {
                arc.residual
            } else {
                self.arcs[arc.sister as usize].residual
            };
            if open > 0.0 {
                self.set_active(arc.head);
            }
            let parent = neighbour.parent;
            if parent != TERMINAL && parent != ORPHAN && neighbour.parent_node == orphan {
                self.make_orphan_back(arc.head);
            }
        }
        self.nodes[orphan as usize].parent = NO_PARENT;
    }

    /// Follows parent arcs from `start` to the terminal and returns `start`'s distance to it, or
    /// [`UNREACHABLE`] if the walk meets an orphan. A node stamped with the current time already
    /// has a checked distance, so the walk stops there.
    fn distance_to_terminal(&mut self, start: u32) -> u32 {
        let mut node = start;
        let mut steps = 0u32;
        loop {
            let state = self.nodes[node as usize];
            if state.timestamp == self.time {
                return steps + state.distance;
            }
            steps += 1;
            match state.parent {
                TERMINAL => {
                    let root = &mut self.nodes[node as usize];
                    root.timestamp = self.time;
                    root.distance = 1;
                    return steps;
                }
                ORPHAN => return UNREACHABLE,
                _ => node = state.parent_node,
            }
        }
    }

    /// Stamps the path from `start` (at `distance`) up to the first node stamped with the current
    /// time, so later origin searches through it stop early.
    fn stamp_path(&mut self, start: u32, mut distance: u32) {
        let mut node = start;
        while self.nodes[node as usize].timestamp != self.time {
            let state = &mut self.nodes[node as usize];
            state.timestamp = self.time;
            state.distance = distance;
            distance -= 1;
            node = state.parent_node;
        }
    }
}
