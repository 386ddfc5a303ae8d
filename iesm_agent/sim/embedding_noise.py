"""Realistic mask embeddings: errors that follow category similarity and neighbours.

For an instance of label l, with category text vectors V (J, D) and similarities S = V V^T:
- a persistent per-object look u = v_l + `instance_bias` x v_c + `instance_structured` x V^T g_o
  + `appearance` x (a_l + a_o) / sqrt(2): c drawn once per object from p_l(c) ~ exp(S[l, c] / T),
  c != l (this armchair looks a bit like a sofa from every side), g_o ~ N(0, I_J) a persistent
  error in the span of the categories, a_l (per category) and a_o (per object) random unit
  vectors orthogonal to the span of the categories: what an image feature holds besides the
  category (orthogonal, so it biases no category: a random a_l would mislabel every wall alike). The appearance part keeps views of
  one object alike (cosine ~0.9, as image features of one object are) while the category part
  stays weak, as for CLIP-like features scored against text;
- per view, a pull s x v_c' towards another similar category (s half-normal x `view_confusion`);
- leaked neighbours: (1 - sum share) u + sum share_j u_j (a mask that leaks into the table under
  a cup carries the table's share);
- structured noise V^T g / |V^T g| (g ~ N(0, I_J)) of norm `structured_noise` x scale and
  isotropic noise of norm `isotropic_noise` x scale, where scale = min(3, sqrt(1 + small_area_px
  / area) x (1 + median depth / far_m)): small and far masks are noisier.
"""

from __future__ import annotations

import zlib

import numpy as np

from .realism import Realism


class EmbeddingNoise:
    """Draws realistic embeddings in the space of `vectors` (label -> unit vector); `seed` fixes
    the per-object looks."""

    def __init__(self, vectors: dict[str, np.ndarray], profile: Realism, seed: int):
        self.names = sorted(vectors)
        self.index = {name: k for k, name in enumerate(self.names)}
        self.v = np.array([vectors[n] for n in self.names], np.float64)
        sim = self.v @ self.v.T
        logits = sim / profile.similarity_temperature
        np.fill_diagonal(logits, -np.inf)
        logits -= logits.max(axis=1, keepdims=True)
        prob = np.exp(logits)
        self.similar = prob / prob.sum(axis=1, keepdims=True)
        self.p, self.seed = profile, seed
        self.basis = np.linalg.qr(self.v.T)[0]  # (D, J) orthonormal basis of the category span
        self._looks: dict[tuple[int, str], np.ndarray] = {}

    def look(self, instance: int, label: str) -> np.ndarray:
        """The persistent (D,) look of one object (not normalised: its parts keep their weights)."""
        key = (instance, label)
        if key not in self._looks:
            rng = np.random.default_rng([self.seed, 101, instance])
            k = self.index[label]
            other = rng.choice(len(self.names), p=self.similar[k])
            g = self.v.T @ rng.standard_normal(len(self.names))
            a_obj = rng.standard_normal(self.v.shape[1])
            a_label = np.random.default_rng([zlib.crc32(label.encode()), 103]).standard_normal(self.v.shape[1])
            a_obj, a_label = self._orthogonal(a_obj), self._orthogonal(a_label)
            u = (self.v[k] + self.p.instance_bias * rng.uniform(0.3, 1.0) * self.v[other]
                 + self.p.instance_structured * g / np.linalg.norm(g)
                 + self.p.appearance * (a_label / np.linalg.norm(a_label) + a_obj / np.linalg.norm(a_obj)) / np.sqrt(2))
            self._looks[key] = u
        return self._looks[key]

    def _orthogonal(self, x: np.ndarray) -> np.ndarray:
        return x - self.basis @ (self.basis.T @ x)

    def embed(self, instance: int, label: str, leaks: dict[int, float], labels: dict[int, str], area: int,
              depth_m: float, rng: np.random.Generator) -> np.ndarray:
        """(D,) float32 unit embedding of one mask showing `instance` (labelled `label`, possibly
        already confused), with `leaks` (other instance -> share of the mask's pixels)."""
        p = self.p
        k = self.index[label]
        own = 1.0 - sum(leaks.values())
        vec = own * self.look(instance, label)
        for other, share in leaks.items():
            vec = vec + share * self.look(other, labels[other])
        pull = rng.choice(len(self.names), p=self.similar[k])
        vec = vec + p.view_confusion * abs(rng.standard_normal()) * self.v[pull]
        scale = min(3.0, np.sqrt(1.0 + p.small_area_px / max(area, 1)) * (1.0 + max(depth_m, 0.0) / p.far_m))
        g = self.v.T @ rng.standard_normal(len(self.names))
        vec = vec + p.structured_noise * scale * g / np.linalg.norm(g)
        iso = rng.standard_normal(vec.shape)
        vec = vec + p.isotropic_noise * scale * iso / np.linalg.norm(iso)
        return (vec / np.linalg.norm(vec)).astype(np.float32)
