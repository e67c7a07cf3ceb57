"""The model and the corpus the query tests (``tree.queries``, compat's) search."""

from __future__ import annotations

from mjcf_model.nodes.base import AnyElement, get_attribute
from mjcf_model.serializers import loads
from tests.conftest import loading_corpus

CORPUS = loading_corpus()


MODEL = loads(
    """
    <mujoco>
      <default><geom group="1"/><default class="vis"><geom rgba="1 0 0 1"/></default></default>
      <worldbody>
        <geom name="floor" size="1 1 0.1" type="plane"/>
        <body name="arm" pos="0 0 1">
          <!-- the arm -->
          <joint name="shoulder" range="-1 1"/>
          <geom name="upper" class="vis" group="1" size="0.1"/>
          <geom name="collide" group="0" size="0.1"/>
          <body name="hand"><site name="tip" size="0.01"/><geom name="hidden" group="3"/></body>
        </body>
        <frame><body name="framed"/></frame>
      </worldbody>
      <tendon><fixed name="t"><joint joint="shoulder" coef="1"/></fixed></tendon>
      <equality><joint joint1="shoulder"/></equality>
      <actuator><motor name="m" joint="shoulder"/><general name="g" joint="shoulder"/></actuator>
      <sensor><touch name="touch" site="tip"/><clock name="clock"/></sensor>
    </mujoco>
    """
)


def _names(elements: tuple[AnyElement, ...] | list[AnyElement]) -> list[object]:
    return [get_attribute(e, "name") for e in elements]
