"""The base model of the schema cases: one model, with every namespace's names its own.

The body ``arm``, the joint ``hinge``, the site ``shoulder``, the tendon ``cord``...:
each case adds what its row needs to this model (see :mod:`tests.support.schema_cases`).
"""

from __future__ import annotations

from collections.abc import Mapping

import attrs


@attrs.frozen
class Case:
    """A model using the reference ``attribute`` of a ``key`` element."""

    #: The schema key of the element whose reference the case uses.
    key: str
    #: The reference attribute.
    attribute: str
    #: The model's text.
    xml: str
    #: Files the model reads, by the path it writes.
    assets: Mapping[str, bytes] = attrs.field(factory=dict)


_BASE = """<mujoco model="case">
  <compiler autolimits="true"/>
  <default>
    <default class="cls"/>{default}
  </default>{extension}
  <asset>
    <mesh name="tet" vertex="0 0 0  0.1 0 0  0.02 0.13 0  0.03 0.01 0.07"/>
    <texture name="checker" type="2d" builtin="checker" width="8" height="8"
             rgb1="1 1 1" rgb2="0 0 0"/>
    <material name="paint" texture="checker"/>{asset}
  </asset>
  <worldbody>
    <camera name="eye" pos="0 -2 1" xyaxes="1 0 0 0 0 1" resolution="8 8"/>
    <body name="arm" pos="0 0 1">
      <joint name="hinge" axis="0 1 0" range="-1 1"/>
      <geom name="upper" size="0.1"/>
      <site name="shoulder" pos="0 0 0.1"/>
      <site name="elbow" pos="0.1 0 0"/>
      <body name="forearm" pos="0 0 -0.5">
        <joint name="slider" type="slide" axis="1 0 0" range="-0.5 0.5"/>
        <geom name="lower" type="capsule" size="0.05 0.1"/>
        <site name="wrist" pos="0 0 -0.1"/>
      </body>
    </body>
    <body name="socket" pos="1 0 1">
      <joint name="swivel" type="ball" range="0 1"/>
      <geom name="knob" size="0.1"/>
    </body>{world}
  </worldbody>
  <tendon>
    <spatial name="cord" range="0 2"><site site="shoulder"/><site site="wrist"/></spatial>
    <fixed name="coupling" range="-1 1"><joint joint="hinge" coef="1"/></fixed>{tendon}
  </tendon>{sections}
</mujoco>
"""


def model(
    *,
    default: str = "",
    extension: str = "",
    asset: str = "",
    world: str = "",
    tendon: str = "",
    raw: str = "",
    **sections: str,
) -> str:
    """The base model with these lines added to its sections (``sections``: new sections).

    ``raw`` is written as it is, after the sections.

    Example:
        >>> "<motor" in model(actuator='<motor joint="hinge"/>')
        True

    """
    extra = "".join(f"\n  <{tag}>\n    {body}\n  </{tag}>" for tag, body in sections.items())
    return _BASE.format(
        default=_indented(default, 4),
        extension=f"\n  <extension>\n    {extension}\n  </extension>" if extension else "",
        asset=_indented(asset, 4),
        world=_indented(world, 4),
        tendon=_indented(tendon, 4),
        sections=extra + _indented(raw, 2),
    )


def _indented(text: str, spaces: int) -> str:
    return f"\n{' ' * spaces}{text}" if text else ""
