"""Engine plugins: the ``<extension>`` section and the ``<plugin>`` elements that use a plugin.

>>> Plugin(instance="cable").instance
'cable'
"""

from __future__ import annotations

from typing import ClassVar

import attrs

from mjcf_model.base import TypedElement
from mjcf_model.values import to_str

__all__ = ["Extension", "ExtensionPlugin", "Plugin", "PluginConfig", "PluginInstance", "PluginUse"]


@attrs.frozen(kw_only=True, repr=False)
class Extension(TypedElement):
    """Section that declares engine plugins."""

    tag: ClassVar[str] = "extension"


@attrs.frozen(kw_only=True, repr=False)
class ExtensionPlugin(TypedElement):
    """An engine plugin used by the model."""

    tag: ClassVar[str] = "plugin"
    #: Identifier of the plugin library.
    plugin: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class PluginInstance(TypedElement):
    """A named, configured instance of a plugin."""

    tag: ClassVar[str] = "instance"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class PluginConfig(TypedElement):
    """One key/value configuration entry of a plugin."""

    tag: ClassVar[str] = "config"
    #: Configuration key.
    key: str | None = attrs.field(default=None, converter=to_str)
    #: Configuration value.
    value: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class PluginUse(TypedElement):
    """Elements that attach a plugin, by library or by instance."""

    #: Name of the plugin instance.
    instance: str | None = attrs.field(default=None, converter=to_str)
    #: Identifier of the plugin library.
    plugin: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class Plugin(PluginUse):
    """A plugin attached to a body, geom, mesh or flexcomp."""

    tag: ClassVar[str] = "plugin"
