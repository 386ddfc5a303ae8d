"""Instance-level 2.5D open-vocabulary mapping from RGB-D frames (paper Sec. 3.1).

`build.build_map(FrameSet) -> SceneMap` runs the pipeline. Scoring a built map (Sec. 4.1), the
matching of built and ground-truth instances and the 2D point-wise baseline live in `evals/`
(`evals.mapping`, `evals.matching`, `evals.baseline2d`).
"""
