"""Instance-level 2.5D open-vocabulary mapping from RGB-D frames (paper Sec. 3.1), its 2D
point-wise baseline and its evaluation (Sec. 4.1).

`build.build_map(FrameSet) -> SceneMap` runs the pipeline; `evaluate.evaluate_map(scene, gt,
frames_dir) -> dict` scores a map; `matching.match_instances(scene, gt)` pairs built and
ground-truth instances (top-down IoU > 0.5).
"""
