// What is on screen, in the page's own words, with the paper's section and equation, and a
// "read more" that says where in the paper the paragraph is (the papers themselves are not part
// of the package). A panel calls explain(element, key) after each step with the key of what the
// step did; the element carries data-history-text, so the history scrubber keeps it per step.

const KWATRA_2005 = 'Kwatra, Essa, Bobick & Kwatra, "Texture Optimization for Example-based Synthesis", SIGGRAPH 2005';
const KWATRA_2003 = 'Kwatra, Schödl, Essa, Turk & Bobick, "Graphcut Textures", SIGGRAPH 2003';

export const EXPLANATIONS = {
  'to-start': {
    text: 'Texture optimization treats synthesis as energy minimisation: the texture energy (1) sums, over a grid of overlapping neighbourhoods x_p of the output, the distance to the nearest exemplar neighbourhood z_p. Press Step to see one iteration.',
    cite: [KWATRA_2005, 'section 3, equation (1) and Algorithm 1', 'the paragraph "We can use the above formulation to perform texture synthesis by iteratively refining an initial estimate..."'],
  },
  'to-level': {
    text: 'A new level (section 3.2): the output is up-sampled or the neighbourhood shrinks, coarse to fine. The energy jumps here, which the paper calls desirable: it helps the algorithm out of poor local minima.',
    cite: [KWATRA_2005, 'section 3.2, Multi-level Synthesis, and Figure 3', 'the paragraph "In Figure 3, we plot the energy of the synthesized texture as a function of number of iterations..."'],
  },
  'to-first-match': {
    text: 'M-step on the new level: every grid node p finds the exemplar neighbourhood z_p nearest to the up-sampled output (a nearest-neighbour search). Shown with step anatomy: the chosen z_p pasted where their nodes are.',
    cite: [KWATRA_2005, 'section 3, the M-step', 'the paragraph "The M-step of our algorithm minimizes (1) with respect to the set of input neighborhoods..."'],
  },
  'to-e-step': {
    text: 'E-step: with every z_p fixed, the output x that minimises energy (1) is a weighted average: each pixel takes the mean of the z_p that overlap it, each z_p weighted by its IRLS weight ||x_p − z_p||^(r−2) (section 3.1).',
    cite: [KWATRA_2005, 'section 3 (the E-step) and section 3.1 (Robust Optimization)', 'the paragraphs "In the E-step, we need to minimize (1) w.r.t. x..." and "The quadratic texture energy as defined in (1) performs least squares estimation..."'],
  },
  'to-m-step': {
    text: 'M-step: with x fixed, each node p takes the exemplar neighbourhood z_p nearest to x_p. The iteration ends when no z_p changes (Algorithm 1) or the iteration cap is reached; the energy per iteration is Figure 3\'s plot.',
    cite: [KWATRA_2005, 'section 3, the M-step, and Algorithm 1', 'the paragraph "The M-step of our algorithm minimizes (1) with respect to the set of input neighborhoods..."'],
  },
  'to-done': {
    text: 'Done: the finest level has converged. The quality line scores the output against the exemplar (coherence, completeness, histogram, flat fraction).',
    cite: [KWATRA_2005, 'section 5, Results', 'the Results section and Figure 3'],
  },
  'gc-start': {
    text: 'Graph-cut textures grow the output from whole copies of the exemplar. Each new patch is cut along the seam of least visible cost, found as the minimum cut of a graph over the overlap.',
    cite: [KWATRA_2003, 'section 3, Patch Fitting using Graph Cuts, and Figure 2', 'the paragraph "Consider the graph shown in Figure 2(right) that has one node per pixel in the overlap region..."'],
  },
  'gc-cover': {
    text: 'Covering the output: the error region (dashed) holds made and unmade pixels, so each patch extends the texture. Its offset is drawn with probability exp(−C(t)/(kσ²)) (section 4) from the matching cost C(t) of every unused offset, computed by FFT (section 5); the seam is the minimum cut of M(s, t, A, B) = ||A(s) − B(s)|| + ||A(t) − B(t)|| (equation 1).',
    cite: [KWATRA_2003, 'section 4, Patch Placement & Matching, and section 3', 'the paragraph "In all these algorithms, we restrict the patch selection to previously unused offsets..."'],
  },
  'gc-refine': {
    text: 'A surrounded region (section 3.2): the output is covered, so the patch goes over the region with the largest seam error. Its border must keep the old pixels; the cut is a closed loop, and old seams become seam nodes (section 3.1) that the new cut can keep, move or erase.',
    cite: [KWATRA_2003, 'section 3.2, Surrounded Regions, section 3.1 and Figure 4', 'the paragraph "So far we have shown new patches that overlap old pixels only along a border region..."'],
  },
  'gc-done': {
    text: 'Done: covered and refined. Toggle seams, seam cost and labels to see where the cuts ran, and the quality line for how close the result is to the exemplar.',
    cite: [KWATRA_2003, 'section 6, Image Synthesis', 'the Image Synthesis section and Figure 5'],
  },
};

/** Writes the explanation `key` into `element` (a short text and a "Read more" disclosure). */
export function explain(element, key) {
  const entry = EXPLANATIONS[key];
  if (!element || !entry || element.dataset.key === key) return;
  element.dataset.key = key;
  const [paper, where, paragraph] = entry.cite;
  element.replaceChildren();
  const text = document.createElement('p');
  text.textContent = entry.text;
  const more = document.createElement('details');
  const summary = document.createElement('summary');
  summary.textContent = 'Read more';
  const cite = document.createElement('p');
  cite.className = 'cite';
  cite.textContent = `${paper}: ${where}; ${paragraph}`;
  more.append(summary, cite);
  element.append(text, more);
}
