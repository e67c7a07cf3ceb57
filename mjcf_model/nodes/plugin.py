"""Engine plugins: the ``<extension>`` section and the ``<plugin>`` elements that use a plugin.

>>> Plugin(instance="cable").instance
'cable'
"""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.base import TypedElement
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import text

__all__ = ["Extension", "ExtensionPlugin", "Plugin", "PluginConfig", "PluginInstance", "PluginUse"]


@node
class Extension(TypedElement):
    """Section that declares engine plugins."""

    schema_keys: ClassVar[tuple[str, ...]] = ("extension",)


@node
class ExtensionPlugin(TypedElement):
    """An engine plugin used by the model."""

    schema_keys: ClassVar[tuple[str, ...]] = ("extension/plugin",)
    #: Identifier of the plugin library.
    plugin: str | None = text()


@node
class PluginInstance(TypedElement):
    """A named, configured instance of a plugin."""

    schema_keys: ClassVar[tuple[str, ...]] = ("extension/plugin/instance",)
    #: Name, unique within its namespace.
    name: str | None = text()


@node
class PluginConfig(TypedElement):
    """One key/value configuration entry of a plugin."""

    schema_keys: ClassVar[tuple[str, ...]] = (
        "extension/plugin/instance/config",
        "asset/mesh/plugin/config",
        "body/geom/plugin/config",
        "body/plugin/config",
        "body/flexcomp/plugin/config",
        "actuator/plugin/config",
        "sensor/plugin/config",
    )
    #: Configuration key.
    key: str | None = text()
    #: Configuration value.
    value: str | None = text()


@node
class PluginUse(TypedElement):
    """Elements that attach a plugin, by library or by instance."""

    #: Name of the plugin instance.
    instance: str | None = text()
    #: Identifier of the plugin library.
    plugin: str | None = text()


@node
class Plugin(PluginUse):
    """A plugin attached to a body, geom, mesh or flexcomp."""

    schema_keys: ClassVar[tuple[str, ...]] = (
        "asset/mesh/plugin",
        "body/geom/plugin",
        "body/plugin",
        "body/flexcomp/plugin",
    )
