"""Simulator realism profiles: how far the rendered frames and the synthetic segmenter stray from
the ground truth.

- `easy`: the original simulator (exact depth, near-flat shading, masks = instance pixels with
  light erosion, embeddings = label text vector + isotropic noise). For unit tests.
- `realistic` (default of `iesm sim`, the demo, the studies and the benchmarks): a structured-light
  depth sensor (noise sigma = `depth_sigma_z2` * z^2 as measured for Kinect-class sensors, no
  reading beyond `depth_max`, at depth edges, on dark and on shiny surfaces, at grazing angles),
  ceiling lights with direction and distance falloff, per-object albedo and texture variation,
  per-frame exposure and white-balance drift; masks whose boundary wanders where colour and depth
  edges are weak (leaking into neighbours); embeddings whose errors follow category similarity,
  carry leaked neighbours' share, persist per object, and grow for small and far masks.

The numbers of `realistic` are calibrated so that single-frame mask categorisation (top-1 over the
scene's categories) falls in the range the paper reports on real data (matching-normalised top-1
0.210 HM3D-Sem .. 0.447 Replica): `python -m iesm_agent.evals.studies.calibration`.
"""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict, Field

from ..errors import IesmError


class Realism(BaseModel):
    """One realism profile (see the module docstring). `name` is what `--realism` takes."""

    model_config = ConfigDict(extra="forbid")

    name: str = "realistic"
    # depth sensor
    depth_sigma_z2: float = Field(0.0, ge=0, description="depth noise sigma per m^2 of depth (m)")
    depth_min: float = Field(0.0, ge=0)
    depth_max: float = Field(10.0, gt=0)
    edge_jump: float = Field(0.08, gt=0, description="relative depth jump to a neighbour that marks an edge")
    edge_dropout: float = Field(0.0, ge=0, le=1)
    dark_level: float = Field(0.12, ge=0, le=1, description="albedo luminance (0-1) below which a surface is dark")
    dark_dropout: float = Field(0.0, ge=0, le=1)
    shiny_dropout: float = Field(0.0, ge=0, le=1, description="metal / glass surfaces")
    grazing_cos: float = Field(0.0, ge=0, le=1, description="no reading where |cos(incidence)| is below this")
    # image formation
    ambient: float = Field(0.985, ge=0, le=1)
    light_strength: float = Field(0.0, ge=0)
    light_falloff: float = Field(3.0, gt=0, description="m at which a light's strength halves")
    albedo_jitter: float = Field(0.0, ge=0, le=0.5)
    texture_amp: float = Field(0.0, ge=0, le=0.5)
    exposure_jitter: float = Field(0.0, ge=0, le=1)
    white_balance_jitter: float = Field(0.0, ge=0, le=0.5)
    pixel_noise: float = Field(2.0, ge=0)
    # masks
    boundary_wander_px: float = Field(0.0, ge=0, description="how far a boundary strays on weak edges")
    # embeddings
    appearance: float = Field(0.0, ge=0, description="weight of the non-category part of an image feature")
    instance_bias: float = Field(0.0, ge=0, description="persistent per-object pull towards a similar category")
    instance_structured: float = Field(0.0, ge=0, description="persistent per-object error among the categories")
    view_confusion: float = Field(0.0, ge=0, description="per-view pull towards a similar category")
    similarity_temperature: float = Field(0.1, gt=0)
    structured_noise: float = Field(0.0, ge=0, description="per-view noise in the span of the category vectors")
    isotropic_noise: float = Field(0.0, ge=0, description="per-view noise in every direction")
    small_area_px: float = Field(1500.0, gt=0, description="masks smaller than this get proportionally more noise")
    far_m: float = Field(6.0, gt=0, description="noise doubles at this median depth")

    @property
    def easy(self) -> bool:
        return self.name == "easy"


EASY = Realism(name="easy")
REALISTIC = Realism(
    name="realistic",
    depth_sigma_z2=0.0028, depth_min=0.4, depth_max=5.5, edge_dropout=0.6, dark_dropout=0.5, shiny_dropout=0.3,
    grazing_cos=0.12, ambient=0.4, light_strength=0.8, light_falloff=3.0, albedo_jitter=0.15, texture_amp=0.08,
    exposure_jitter=0.15, white_balance_jitter=0.05, pixel_noise=3.0, boundary_wander_px=3.0, small_area_px=1000.0,
    far_m=8.0,
    appearance=7.0, instance_bias=0.6, instance_structured=1.0, view_confusion=0.7, similarity_temperature=0.08,
    structured_noise=1.4, isotropic_noise=0.2,
)
PROFILES = {"easy": EASY, "realistic": REALISTIC}


def get_profile(name: str | Realism | None) -> Realism:
    """A profile by name ("easy", "realistic"; None = realistic) or as given."""
    if isinstance(name, Realism):
        return name
    if name is None:
        return REALISTIC
    try:
        return PROFILES[name]
    except KeyError:
        raise IesmError(f"unknown realism profile {name!r} (choose from {', '.join(PROFILES)})", None,
                        "--realism") from None
