"""Scaling shapes made by MuJoCo's signed-distance-field (SDF) plugins.

A mesh or geom made by an SDF plugin (``<mesh><plugin instance="..."/></mesh>``)
refuses a ``scale`` attribute: its size is in the plugin's settings
(``<config key=... value=...>``, on an ``<instance>`` under ``<extension>`` or
inline). Of the SDF plugins MuJoCo ships (3.9 and 4.0: ``mujoco.sdf.torus``,
``bowl``, ``gear``, ``bolt`` and ``nut``), the torus, the bowl and the gear have
their lengths in settings; they scale by the mean factor, and a setting not
written is written with the plugin's default, scaled. The gear's
``innerdiameter`` has no such default: unwritten or negative, MuJoCo derives the
bore from ``diameter`` (so it scales with it), and a written one scales keeping
its sign. Its ``teeth`` and ``alpha`` (an angle) stay. The bolt and nut have
their dimensions fixed in the plugin's code (their only setting is a thread
radius), so scaling a model that makes a mesh or geom with them, or with any
other plugin, raises an error naming the plugin.

>>> SDF_LENGTHS["mujoco.sdf.torus"]
mappingproxy({'radius1': 0.35, 'radius2': 0.15})
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from types import MappingProxyType

from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import AnyElement, get_attribute
from mjcf_model.nodes.plugin import PluginConfig
from mjcf_model.transforms.scaling.context import ScaleContext, times
from mjcf_model.transforms.scaling.pieces import Changes
from mjcf_model.tree.traversal import keyed_walk, with_children
from mjcf_model.values import format_value, numbers_of

__all__ = [
    "SDF_LENGTHS",
    "SDF_SETTINGS_KEYS",
    "makes_sdf",
    "sdf_config",
    "sdf_mesh_scale",
    "with_sdf_settings",
]

#: The SDF plugins whose shape scales through their settings: each length
#: setting and its default (from the plugins' sources, as shipped in 3.9 and 4.0),
#: ``None`` for one MuJoCo derives from the others when it is not written.
SDF_LENGTHS: Mapping[str, Mapping[str, float | None]] = MappingProxyType(
    {
        "mujoco.sdf.torus": MappingProxyType({"radius1": 0.35, "radius2": 0.15}),
        "mujoco.sdf.bowl": MappingProxyType({"height": 0.4, "radius": 1.0, "thickness": 0.02}),
        "mujoco.sdf.gear": MappingProxyType(
            {"diameter": 2.8, "thickness": 0.2, "innerdiameter": None}
        ),
    }
)

#: MuJoCo's SDF plugins whose dimensions are fixed in code.
_FIXED_SHAPES = frozenset({"mujoco.sdf.bolt", "mujoco.sdf.nut"})

#: The schema keys of elements that make a shape with a plugin.
_SHAPE_USES = frozenset({"asset/mesh/plugin", "body/geom/plugin"})
#: The keys of the elements :func:`with_sdf_settings` completes or refuses.
SDF_SETTINGS_KEYS = _SHAPE_USES | {"extension/plugin/instance"}


def _instances(context: ScaleContext) -> dict[str, str]:
    """Each plugin instance's name, mapped to its plugin."""
    found: dict[str, str] = {}
    for element, key, ancestors in keyed_walk(context.model) if context.model else ():
        name = get_attribute(element, "name")
        if key == "extension/plugin/instance" and isinstance(name, str):
            found[name] = str(get_attribute(ancestors[-1], "plugin"))
    return found


def _plugin_of(element: AnyElement, context: ScaleContext) -> str | None:
    """The plugin a ``<plugin>`` use names, directly or through its instance."""
    plugin = get_attribute(element, "plugin")
    if isinstance(plugin, str):
        return plugin
    instance = get_attribute(element, "instance")
    return context.cached("plugin instances", lambda: _instances(context)).get(str(instance))


def _refuse(plugin: str | None, owner: str) -> None:
    if plugin in SDF_LENGTHS:
        return
    why = (
        "its dimensions are fixed in the plugin's code"
        if plugin in _FIXED_SHAPES
        else "mjcf-model does not know which of its settings are lengths"
    )
    raise MjcfValueError(
        f"cannot scale the {owner} made by plugin {plugin!r}: {why}; only "
        f"{', '.join(SDF_LENGTHS)} scale. Replace that shape (or scale its settings "
        "yourself and take it out of the model) before scaling"
    )


def sdf_config(
    element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
) -> Changes:
    """Scale a ``<config>`` value when it is a length setting of an SDF plugin.

    Examples:
        >>> from mjcf_model import ExtensionPlugin, PluginInstance
        >>> from mjcf_model.transforms.scaling.context import ScaleContext
        >>> owners = (ExtensionPlugin(plugin="mujoco.sdf.torus"), PluginInstance(name="t"))
        >>> config = PluginConfig(key="radius1", value="0.2")
        >>> sdf_config(config, owners, ScaleContext(factors=(2.0, 2.0, 2.0)))
        {'value': '0.4'}

    """
    owner = ancestors[-1] if ancestors else None
    if owner is not None and owner.tag == "instance":
        owner = ancestors[-2] if len(ancestors) > 1 else None
    plugin = get_attribute(owner, "plugin") if owner is not None else None
    key, value = get_attribute(element, "key"), get_attribute(element, "value")
    if key not in SDF_LENGTHS.get(str(plugin), {}) or value is None or numbers_of(value) is None:
        return {}
    return {"value": times(value, context.mean)}


def with_sdf_settings(
    element: AnyElement, key: str, ancestors: Sequence[AnyElement], context: ScaleContext
) -> AnyElement:
    """Complete an SDF plugin's settings with its scaled defaults; refuse other shape plugins.

    ``element`` is a plugin ``<instance>`` or a mesh's or geom's ``<plugin>``,
    its settings already scaled by :func:`sdf_config`.

    Examples:
        >>> from mjcf_model import ExtensionPlugin, PluginInstance
        >>> from mjcf_model.transforms.scaling.context import ScaleContext
        >>> owners = (ExtensionPlugin(plugin="mujoco.sdf.torus"),)
        >>> done = with_sdf_settings(PluginInstance(name="t"), "extension/plugin/instance",
        ...                          owners, ScaleContext(factors=(2.0, 2.0, 2.0)))
        >>> [(c.key, c.value) for c in done.elements]
        [('radius1', '0.7'), ('radius2', '0.3')]

    """
    if key == "extension/plugin/instance":
        plugin = get_attribute(ancestors[-1], "plugin") if ancestors else None
    elif key in _SHAPE_USES:
        plugin = _plugin_of(element, context)
        _refuse(plugin, "mesh" if key.startswith("asset") else "geom")
        if get_attribute(element, "instance") is not None:
            return element
    else:
        return element
    defaults = SDF_LENGTHS.get(str(plugin))
    if defaults is None:
        return element
    written = {get_attribute(c, "key") for c in element.elements if c.tag == "config"}
    missing = [
        PluginConfig(key=name, value=format_value(default * context.mean))
        for name, default in defaults.items()
        if name not in written and default is not None
    ]
    return with_children(element, [*element.children, *missing]) if missing else element


def sdf_mesh_scale(
    mesh: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
) -> Changes:
    """A mesh made by a plugin keeps ``scale`` unset (MuJoCo refuses one on such meshes).

    When a default class gives meshes a scale (scaled there), such a mesh writes
    the unscaled value it had, so it stays the one MuJoCo accepted.

    Examples:
        >>> from mjcf_model import Mesh, Plugin
        >>> from mjcf_model.transforms.scaling.context import ScaleContext
        >>> mesh = Mesh(children=[Plugin(instance="t")])
        >>> sdf_mesh_scale(mesh, (), ScaleContext(factors=(2.0, 2.0, 2.0)))
        {}

    """
    if get_attribute(mesh, "scale") is not None:
        return {}
    inherited = context.classes.resolve(mesh, ancestors, "scale")
    return {} if inherited is None else {"scale": inherited}


def makes_sdf(mesh: AnyElement) -> bool:
    """Whether a mesh is made by a plugin.

    Examples:
        >>> from mjcf_model import Mesh, Plugin
        >>> makes_sdf(Mesh(children=[Plugin(instance="t")])), makes_sdf(Mesh(file="a.stl"))
        (True, False)

    """
    return bool(mesh.children) and any(child.tag == "plugin" for child in mesh.elements)
