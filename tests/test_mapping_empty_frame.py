"""A frame whose segmenter found nothing (K = 0 masks) is a normal frame, not an error."""

import numpy as np

from iesm_agent.mapping.project import mask_points, project_candidates


def test_a_frame_without_masks_projects_to_no_candidates():
    depth, pose = np.ones((4, 5), np.float32), np.eye(4)
    masks = np.zeros((0, 4, 5), bool)
    assert len(project_candidates(depth, masks, 1.0, 1.0, 2.0, 1.5, pose, 0.05)) == 0
    k, keys, z, area = mask_points(depth, masks, 1.0, 1.0, 2.0, 1.5, pose, 0.05)
    assert len(k) == len(keys) == len(z) == len(area) == 0
