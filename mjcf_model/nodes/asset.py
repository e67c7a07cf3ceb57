"""The ``<asset>`` section: meshes, textures, materials, height fields, skins and model assets.

>>> Material(name="red", rgba="1 0 0 1").rgba
(1.0, 0.0, 0.0, 1.0)
"""

from __future__ import annotations

from typing import ClassVar

import attrs

from mjcf_model.base import TypedElement
from mjcf_model.values import (
    Floats,
    Ints,
    float_key,
    to_bool,
    to_float,
    to_floats,
    to_int,
    to_ints,
    to_str,
    to_vec2,
    to_vec3,
    to_vec4,
)

__all__ = [
    "Asset",
    "Bone",
    "Hfield",
    "Material",
    "MaterialLayer",
    "Mesh",
    "Model",
    "Skin",
    "Texture",
]


@attrs.frozen(kw_only=True, repr=False)
class Asset(TypedElement):
    """Section of assets: meshes, textures, materials, height fields, skins, models."""

    tag: ClassVar[str] = "asset"

    @property
    def meshes(self) -> tuple[Mesh, ...]:
        """The mesh assets."""
        return self._of_type(Mesh)

    @property
    def textures(self) -> tuple[Texture, ...]:
        """The texture assets."""
        return self._of_type(Texture)

    @property
    def materials(self) -> tuple[Material, ...]:
        """The material assets."""
        return self._of_type(Material)

    @property
    def hfields(self) -> tuple[Hfield, ...]:
        """The height-field assets."""
        return self._of_type(Hfield)

    @property
    def skins(self) -> tuple[Skin, ...]:
        """The skin assets."""
        return self._of_type(Skin)

    @property
    def models(self) -> tuple[Model, ...]:
        """The model assets."""
        return self._of_type(Model)


@attrs.frozen(kw_only=True, repr=False)
class Mesh(TypedElement):
    """A mesh asset, from a file, inline vertices or a built-in shape."""

    tag: ClassVar[str] = "mesh"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = attrs.field(default=None, converter=to_str, metadata={"xml": "class"})
    #: Procedurally generated content.
    builtin: str | None = attrs.field(default=None, converter=to_str)
    #: MIME type of the file.
    content_type: str | None = attrs.field(default=None, converter=to_str)
    #: Face vertex indices.
    face: Ints | None = attrs.field(default=None, converter=to_ints)
    #: File name, relative to the model (or asset) directory.
    file: str | None = attrs.field(default=None, converter=to_str)
    #: How inertia is computed from the mesh.
    inertia: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the material asset used for rendering.
    material: str | None = attrs.field(default=None, converter=to_str)
    #: Maximum number of convex-hull vertices.
    maxhullvert: int | None = attrs.field(default=None, converter=to_int)
    #: Vertex normals.
    normal: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Parameters of a built-in mesh.
    params: str | None = attrs.field(default=None, converter=to_str)
    #: Reference position the mesh vertices are expressed relative to.
    refpos: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Reference orientation of the mesh vertices.
    refquat: Floats | None = attrs.field(default=None, converter=to_vec4)
    #: Scale factor(s).
    scale: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Whether to smooth normals.
    smoothnormal: str | None = attrs.field(default=None, converter=to_str)
    #: Texture coordinates.
    texcoord: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Vertex coordinates.
    vertex: Floats | None = attrs.field(default=None, converter=to_floats)


@attrs.frozen(kw_only=True, repr=False)
class Hfield(TypedElement):
    """A height-field asset."""

    tag: ClassVar[str] = "hfield"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Size parameters; their number and meaning depend on ``type``.
    size: Floats | None = attrs.field(default=None, converter=to_vec4)
    #: MIME type of the file.
    content_type: str | None = attrs.field(default=None, converter=to_str)
    #: Elevation data.
    elevation: str | None = attrs.field(default=None, converter=to_str)
    #: File name, relative to the model (or asset) directory.
    file: str | None = attrs.field(default=None, converter=to_str)
    #: Number of columns of elevation data.
    ncol: int | None = attrs.field(default=None, converter=to_int)
    #: Number of rows of elevation data.
    nrow: int | None = attrs.field(default=None, converter=to_int)


@attrs.frozen(kw_only=True, repr=False)
class Skin(TypedElement):
    """A skinned mesh deformed by bones."""

    tag: ClassVar[str] = "skin"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Face vertex indices.
    face: Ints | None = attrs.field(default=None, converter=to_ints)
    #: File name, relative to the model (or asset) directory.
    file: str | None = attrs.field(default=None, converter=to_str)
    #: Integer group, used for visualization filters and by convention.
    group: int | None = attrs.field(default=None, converter=to_int)
    #: Distance by which skin vertices are pushed out along their normals.
    inflate: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Name of the material asset used for rendering.
    material: str | None = attrs.field(default=None, converter=to_str)
    #: Colour and transparency (r, g, b, a).
    rgba: Floats | None = attrs.field(default=None, converter=to_vec4)
    #: Texture coordinates.
    texcoord: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Vertex coordinates.
    vertex: Floats | None = attrs.field(default=None, converter=to_floats)


@attrs.frozen(kw_only=True, repr=False)
class Bone(TypedElement):
    """A bone of a skin: a body and the vertices it moves."""

    tag: ClassVar[str] = "bone"
    #: Bind position of the bone.
    bindpos: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Bind orientation of the bone.
    bindquat: Floats | None = attrs.field(default=None, converter=to_vec4)
    #: Name of the body.
    body: str | None = attrs.field(default=None, converter=to_str)
    #: Indices of the skin vertices this bone moves.
    vertid: Ints | None = attrs.field(default=None, converter=to_ints)
    #: Weights of the skin vertices this bone moves.
    vertweight: Floats | None = attrs.field(default=None, converter=to_floats)


@attrs.frozen(kw_only=True, repr=False)
class Texture(TypedElement):
    """A texture asset, from files or built in."""

    tag: ClassVar[str] = "texture"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = attrs.field(default=None, converter=to_str, metadata={"xml": "class"})
    #: Element type keyword.
    type: str | None = attrs.field(default=None, converter=to_str)
    #: Procedurally generated content.
    builtin: str | None = attrs.field(default=None, converter=to_str)
    #: Colour space of the image.
    colorspace: str | None = attrs.field(default=None, converter=to_str)
    #: MIME type of the file.
    content_type: str | None = attrs.field(default=None, converter=to_str)
    #: Whether the image is embedded in compiled output.
    embed: str | None = attrs.field(default=None, converter=to_str)
    #: File name, relative to the model (or asset) directory.
    file: str | None = attrs.field(default=None, converter=to_str)
    #: File of the back face of a cube texture.
    fileback: str | None = attrs.field(default=None, converter=to_str)
    #: File of the down face of a cube texture.
    filedown: str | None = attrs.field(default=None, converter=to_str)
    #: File of the front face of a cube texture.
    filefront: str | None = attrs.field(default=None, converter=to_str)
    #: File of the left face of a cube texture.
    fileleft: str | None = attrs.field(default=None, converter=to_str)
    #: File of the right face of a cube texture.
    fileright: str | None = attrs.field(default=None, converter=to_str)
    #: File of the up face of a cube texture.
    fileup: str | None = attrs.field(default=None, converter=to_str)
    #: Layout of the faces in the grid.
    gridlayout: str | None = attrs.field(default=None, converter=to_str)
    #: Grid size of a cube or skybox texture in one file.
    gridsize: Ints | None = attrs.field(default=None, converter=to_ints)
    #: Height.
    height: int | None = attrs.field(default=None, converter=to_int)
    #: Whether to flip the image horizontally.
    hflip: bool | None = attrs.field(default=None, converter=to_bool)
    #: Marking of a built-in texture.
    mark: str | None = attrs.field(default=None, converter=to_str)
    #: Colour of the marking.
    markrgb: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Number of colour channels.
    nchannel: int | None = attrs.field(default=None, converter=to_int)
    #: Probability of random dots in a built-in texture.
    random: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: First colour of a built-in texture.
    rgb1: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Second colour of a built-in texture.
    rgb2: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Whether to flip the image vertically.
    vflip: bool | None = attrs.field(default=None, converter=to_bool)
    #: Width.
    width: int | None = attrs.field(default=None, converter=to_int)


@attrs.frozen(kw_only=True, repr=False)
class Material(TypedElement):
    """A material asset."""

    tag: ClassVar[str] = "material"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = attrs.field(default=None, converter=to_str, metadata={"xml": "class"})
    #: Emission, as a multiple of the colour.
    emission: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Metallic value for physically based rendering.
    metallic: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Reflectance.
    reflectance: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Colour and transparency (r, g, b, a).
    rgba: Floats | None = attrs.field(default=None, converter=to_vec4)
    #: Roughness value for physically based rendering.
    roughness: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Shininess.
    shininess: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Specular colour or intensity.
    specular: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: How many times the texture repeats.
    texrepeat: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Name of the texture asset.
    texture: str | None = attrs.field(default=None, converter=to_str)
    #: Whether texture repetition is in world units.
    texuniform: bool | None = attrs.field(default=None, converter=to_bool)


@attrs.frozen(kw_only=True, repr=False)
class MaterialLayer(TypedElement):
    """A texture layer of a material."""

    tag: ClassVar[str] = "layer"
    #: Role of the texture layer.
    role: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the texture asset.
    texture: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class Model(TypedElement):
    """A model asset (another MJCF file) for ``<attach>``."""

    tag: ClassVar[str] = "model"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: MIME type of the file.
    content_type: str | None = attrs.field(default=None, converter=to_str)
    #: File name, relative to the model (or asset) directory.
    file: str | None = attrs.field(default=None, converter=to_str)
