// What is on screen, in the page's own words, with the paper's section and equation, and a
// "read more" that says where in the paper the paragraph is (the papers themselves are not part
// of the package). A panel calls explain(element, key) after each step with the key of what the
// step did; the element carries data-history-text, so the history scrubber keeps it per step.

const KWATRA_2005 = 'Kwatra, Essa, Bobick & Kwatra, "Texture Optimization for Example-based Synthesis", SIGGRAPH 2005';
const KWATRA_2003 = 'Kwatra, Schödl, Essa, Turk & Bobick, "Graphcut Textures", SIGGRAPH 2003';

const SHEN_2009 = 'Shen, Jin, Mao & Feng, "A unified framework for designing textures using energy optimization", Pattern Recognition 2009 (Shen et al.)';
const WU_YU_2004 = 'Wu & Yu, "Feature Matching and Deformation for Texture Synthesis", SIGGRAPH 2004';
const HERTZMANN_2001 = 'Hertzmann, Jacobs, Oliver, Curless & Salesin, "Image Analogies", SIGGRAPH 2001';

export const EXPLANATIONS = {
  'to-start': {
    text: 'Texture optimization treats synthesis as energy minimisation: the texture energy (1) sums, over a grid of overlapping neighbourhoods x_p of the output, the distance to the nearest exemplar neighbourhood z_p. The coarsest level starts from a quick graph-cut synthesis (graph-cut textures, sub-patch matching; the paper starts at random) so that lattices and large elements begin whole. Press Step to see one iteration.',
    cite: [KWATRA_2005, 'section 3, equation (1) and Algorithm 1', 'the paragraph "We can use the above formulation to perform texture synthesis by iteratively refining an initial estimate..."'],
  },
  'to-guided-start': {
    text: 'Guided synthesis: a source guide (the exemplar\'s luminance) and a target guide (shown beside the output) add weight · ||g_source − g_target||² to the M-step\'s distance, so each z_p must look like the exemplar and have the guide value the target asks for where its node is. With a photo as the target guide this is the texture transfer of image analogies: the output draws the photo with the exemplar\'s texture.',
    cite: [HERTZMANN_2001, 'section 4.4, Texture transfer (guides as in section 3; texture-by-numbers in section 4.6)', 'the paragraph on texture transfer, where the weight trades matching the texture against matching the target'],
  },
  'to-guided-m-step': {
    text: 'M-step with guides: each node p takes the exemplar neighbourhood z_p nearest to x_p in colour plus weight times the squared difference of the guides (the exemplar\'s luminance there against the target guide at p). The E-step still averages colours only, so the guide acts through the matches.',
    cite: [HERTZMANN_2001, 'section 4.4, Texture transfer, with Kwatra et al. 2005 section 3 (the M-step)', 'the paragraph on texture transfer, where the weight trades matching the texture against matching the target'],
  },
  'to-level': {
    text: 'A new level (section 3.2): the output is up-sampled or the neighbourhood shrinks, coarse to fine. The energy jumps here, which the paper calls desirable: it helps the algorithm out of poor local minima.',
    cite: [KWATRA_2005, 'section 3.2, Multi-level Synthesis, and Figure 3', 'the paragraph "In Figure 3, we plot the energy of the synthesized texture as a function of number of iterations..."'],
  },
  'to-graphcut-start': {
    text: 'Making the start: on a large output the coarsest level\'s graph-cut synthesis takes several steps. Random exemplar patches (option start: \'patches\') would start every lattice at a phase per patch, and EM only moves what it finds nearby: the paper\'s "misalignment of texture elements".',
    cite: [KWATRA_2005, 'section 6, the limitation of local minima; the start is graph-cut textures (Kwatra et al. 2003, section 4.1, sub-patch matching)', 'the paragraph "A limitation of our technique is that because it tries to decrease the energy at each iteration, it can get stuck in local minima..."'],
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
  'mg-start': {
    text: 'Interactive merging: the images are laid down as patches, one after another, and each graph cut finds the seam between the new image and what is there. Painted pixels become constraint arcs of infinite capacity to the image they are painted for, so the cut must route around them.',
    cite: [KWATRA_2003, 'section 3 (constraint arcs, Figure 2) and section 6, Image Synthesis (interactive merging, Figure 6)', 'the paragraph "Consider the graph shown in Figure 2(right)..." on constraint arcs'],
  },
  'mg-done': {
    text: 'Merged: the red seams are the minimum cuts between the images that respect the paint. Repaint and run again to move them.',
    cite: [KWATRA_2003, 'section 6 and Figure 6', 'the caption of Figure 6 (the merged banner)'],
  },
  'fl-first': {
    text: 'Frame 1 is ordinary texture optimization, coarse to fine. Every later frame starts from the previous one warped along the flow.',
    cite: [KWATRA_2005, 'section 4.1, Flow-guided Synthesis', 'the paragraph "We perform synthesis in a frame-by-frame fashion..."'],
  },
  'fl-frame': {
    text: 'A flow frame: the warped previous frame is both the start and a soft constraint, weighted by λ in the flow energy (3); the texture energy keeps it looking like the exemplar. The naive view beside it only warps, and smears.',
    cite: [KWATRA_2005, 'section 4.1, equation (3), and section 4 (soft constraints, equation (2))', 'the paragraph "We perform synthesis in a frame-by-frame fashion..."'],
  },
  'fl-e-step': {
    text: 'E-step of a flow frame: with the z_p fixed, each pixel becomes a weighted average of the matched neighbourhoods that overlap it and of the warped previous frame, weighted by λ (the flow energy (3), treated as the soft constraint of (2)). Compare "after the E-step" with the warped target beside it: the texture pulls one way, the flow the other. The last iteration at each neighbourhood size ends here: its M-step would only find matches for the next frame, which searches again from them anyway, so this library only measures them.',
    cite: [KWATRA_2005, 'section 4.1, equation (3), with section 4 (the E-step of soft-constrained synthesis)', 'the paragraphs "We perform synthesis in a frame-by-frame fashion..." and "In the E-step, we solve a new system of linear equations..."'],
  },
  'fl-m-step': {
    text: 'M-step of a flow frame: each grid node takes the exemplar neighbourhood z_p nearest to the frame, searched from its match in the previous frame carried along the flow (Algorithm 2). An M-step changes no pixel; shown is what it chose, pasted where the nodes are.',
    cite: [KWATRA_2005, 'section 4.1 and Algorithm 2', 'the paragraph "We perform synthesis in a frame-by-frame fashion..." and the M-step of section 4 ("We also modify the M-step that estimates {z_p}...")'],
  },
  'fg-features': {
    text: 'Feature-guided synthesis: each new patch is chosen by its feature cost (curvilinear features matched in position and orientation, section 2.1) plus 0.5 × its colour difference, bent by a thin-plate spline so its features meet those placed (section 2.2), then cut in with a graph-cut seam.',
    cite: [WU_YU_2004, 'sections 2.1-2.3 and 3', 'the section "3 Feature-Guided Texture Synthesis"'],
  },
  'fg-hybrid': {
    text: 'Feature-guided graph-cut placement (the default): the whole exemplar is the patch, placed over graph cut\'s error region. The best offsets by colour are re-ranked by colour plus the feature cost (curvilinear features matched in position and orientation, section 2.1; weight 0.5, section 3) and one is drawn by eq. 3; the seam also pays where it would end a curve. No warp here: the thin-plate spline of section 2.2 bends the patches of the scan placement.',
    cite: [WU_YU_2004, 'sections 2.1 and 3, with Kwatra et al. 2003 sections 3-4', 'the section "3 Feature-Guided Texture Synthesis"'],
  },
  'fg-graphcut': {
    text: 'The same exemplar and seed through plain graph cut, for comparison: count where features end at a seam (broken features, lower is better).',
    cite: [KWATRA_2003, 'section 4, entire patch matching', 'the paragraph on entire patch matching'],
  },
  'vt-start': {
    text: 'Video textures: the graph is over voxels (x, y, t) and a patch is a spatio-temporal block of the clip; a loop needs only a seam in time, found by the same minimum cut.',
    cite: [KWATRA_2003, 'section 7, Video Synthesis', 'the section "7 Video Synthesis"'],
  },
  'vt-place': {
    text: 'A spatio-temporal patch: its offset (x, y, t) is drawn with probability exp(−C/(kσ²)) from the costs C of every translation that covers the error region, one 3-D FFT search (equation (4), section 5); its seam is a surface, the minimum cut of a graph over 6-connected voxels. Shown: the costs at the drawn time shift, and the graph in the frame of the patch with the most overlap.',
    cite: [KWATRA_2003, 'section 7 (C. Spatio-Temporally Stationary Videos), section 4 (sub-patch matching, equations (3) and (4)) and section 5 (FFT-based acceleration)', 'the paragraphs "C. Spatio-Temporally Stationary Videos..." and "Sub-patch matching: This is the most general of all our patch selection techniques..."'],
  },
  'vt-place-entire': {
    text: 'A spatio-temporal patch by entire-patch matching: its offset (x, y, t) is drawn with probability exp(−C/(kσ²)), where C is the squared difference between the whole clip at that offset and every covered voxel it overlaps, divided by the overlap (equation (2) in three dimensions), from one 3-D FFT search over all the offsets that cover the error region; its seam is a surface, the minimum cut of a graph over 6-connected voxels. Shown: the costs at the drawn time shift, and the graph in the frame of the patch with the most overlap.',
    cite: [KWATRA_2003, 'section 4 (entire patch matching, equations (2) and (3)) and section 7', 'the paragraph on entire patch matching'],
  },
  'vt-place-random': {
    text: 'A spatio-temporal patch at a random offset (section 7, B. Random Temporal Offsets, or a random spatial one): there is no cost surface to show, only its seam surface, the minimum cut of a graph over 6-connected voxels, shown in the frame of the patch with the most overlap.',
    cite: [KWATRA_2003, 'section 7 (B. Random Temporal Offsets) and section 3 (the graph, Figure 2)', 'the paragraph "B. Random Temporal Offsets: For very short sequences of video..."'],
  },
  'ip-start': {
    text: 'Fill a hole: paint over what should go (an object, a scratch, a corner), then Step. The hole is filled from the rest of the image in two passes: a graph-cut fill, patch by patch from the outside in, with the known pixels held by constraint arcs, then texture optimisation over the hole with the known pixels as hard constraints. Pixels outside the hole never change.',
    cite: [KWATRA_2003, 'section 3 (constraint arcs, Figure 2) and section 4; then Kwatra et al. 2005, section 4 (constrained synthesis)', 'the paragraph "Consider the graph shown in Figure 2(right)..." on constraint arcs'],
  },
  'ip-uncrop': {
    text: 'Uncrop: the image is put inside a new border, and the border is the hole. The same fill grows the texture outwards from the image\'s edges, then texture optimisation smooths what it laid, the image itself held fixed.',
    cite: [KWATRA_2003, 'section 3 (constraint arcs) and section 4, Patch Placement & Matching', 'the paragraph "Consider the graph shown in Figure 2(right)..." on constraint arcs'],
  },
  'ip-fill': {
    text: 'A fill patch: it is centred on the hole\'s front where its window holds the most known or filled pixels, so the fill grows inwards from where most is known. Its source window is drawn with probability exp(−C/(kσ²)) (eq. 3) from the SSD C over the overlap (eq. 2, by FFT, section 5), and the minimum cut lays it in: known pixels are tied to the old side by infinite constraint arcs, unfilled ones must take the patch, and old seams are remembered (section 3.1).',
    cite: [KWATRA_2003, 'sections 3 and 3.1 (the seam graph, constraint arcs, old seams), section 4 (equations (2) and (3)) and section 5 (FFT search)', 'the paragraph "Consider the graph shown in Figure 2(right) that has one node per pixel in the overlap region..."'],
  },
  'ip-optimization': {
    text: 'Texture optimisation over the hole and a margin of known pixels, started from the fill: the M-step matches every neighbourhood to one of the image outside the hole, the E-step averages them, and the known pixels are hard constraints (the soft constraints of section 4 with λ taken to infinity). The energy falls as the fill\'s seams are smoothed.',
    cite: [KWATRA_2005, 'section 3 (the E- and M-steps, energy (1)) and section 4 (controllable synthesis, Algorithm 2)', 'the paragraph "The M-step of our algorithm minimizes (1) with respect to the set of input neighborhoods..."'],
  },
  'ip-done': {
    text: 'Done: every hole pixel is filled, and every other pixel is exactly the input\'s. Toggle fill patches to see which patch each filled pixel came from; the energy plot shows what the optimisation changed after the fill.',
    cite: [KWATRA_2003, 'section 3 (constraint arcs) and section 6, Image Synthesis', 'the Image Synthesis section and Figure 6'],
  },
  'ds-deform': {
    text: 'Global deformation: the texture is rotated, scaled, mirrored or flipped as a whole, then re-synthesised by energy optimization so that it stays seamless.',
    cite: [SHEN_2009, 'section 3.1, Algorithm overview', 'the paragraph "Our interactive scheme allows the texture designer..."'],
  },
  'ds-brush': {
    text: 'Local deformation with a brush: a graph-cut labelling decides which pixels take the brushed texture, and Poisson blending removes the seam.',
    cite: [SHEN_2009, 'section 3.2, Interactive local-texture deformation using energy optimization', 'the section 3.2'],
  },
  'ds-synthesis': {
    text: 'Texture optimization with a wavelet texture energy: neighbourhoods are compared by their wavelet coefficients as well as their pixels, which keeps the detail the plain energy averages away.',
    cite: [SHEN_2009, 'section 3.3, Wavelet-based texture design using energy optimization', 'the section 3.3'],
  },
  'ds-layers': {
    text: 'Layer-based design: textures are laid down as layers whose patches are placed by energy, fast enough to paint with.',
    cite: [SHEN_2009, 'section 3.4, Fast layer-based texture design', 'the section 3.4'],
  },
  'ds-tileable': {
    text: 'Tileable (cyclic) textures: the borders are re-synthesised so that the texture continues across them when tiled.',
    cite: [SHEN_2009, 'section 4, Designing cyclic textures using energy optimization', 'the section 4'],
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
