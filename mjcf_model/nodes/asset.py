"""The ``<asset>`` section: meshes, textures, materials, height fields, skins and model assets.

>>> Material(name="red", rgba="1 0 0 1").rgba
(1.0, 0.0, 0.0, 1.0)
"""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.base import TypedElement
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import (
    boolean,
    integer,
    integers,
    number,
    numbers,
    text,
    vec2,
    vec3,
    vec4,
)
from mjcf_model.values import Floats, Ints

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


@node
class Asset(TypedElement):
    """Section of assets: meshes, textures, materials, height fields, skins, models."""

    schema_keys: ClassVar[tuple[str, ...]] = ("asset",)

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


@node
class Mesh(TypedElement):
    """A mesh asset, from a file, inline vertices or a built-in shape."""

    schema_keys: ClassVar[tuple[str, ...]] = ("asset/mesh", "default/mesh")
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = text(xml="class")
    #: Procedurally generated content.
    builtin: str | None = text()
    #: MIME type of the file.
    content_type: str | None = text()
    #: Face vertex indices.
    face: Ints | None = integers()
    #: File name, relative to the model (or asset) directory.
    file: str | None = text()
    #: How inertia is computed from the mesh.
    inertia: str | None = text()
    #: Name of the material asset used for rendering.
    material: str | None = text()
    #: Maximum number of convex-hull vertices.
    maxhullvert: int | None = integer()
    #: Vertex normals.
    normal: Floats | None = numbers()
    #: Parameters of a built-in mesh.
    params: str | None = text()
    #: Reference position the mesh vertices are expressed relative to.
    refpos: Floats | None = vec3()
    #: Reference orientation of the mesh vertices.
    refquat: Floats | None = vec4()
    #: Scale factor(s).
    scale: Floats | None = vec3()
    #: Whether to smooth normals.
    smoothnormal: str | None = text()
    #: Texture coordinates.
    texcoord: Floats | None = numbers()
    #: Vertex coordinates.
    vertex: Floats | None = numbers()


@node
class Hfield(TypedElement):
    """A height-field asset."""

    schema_keys: ClassVar[tuple[str, ...]] = ("asset/hfield",)
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Size parameters; their number and meaning depend on ``type``.
    size: Floats | None = vec4()
    #: MIME type of the file.
    content_type: str | None = text()
    #: Elevation data.
    elevation: str | None = text()
    #: File name, relative to the model (or asset) directory.
    file: str | None = text()
    #: Number of columns of elevation data.
    ncol: int | None = integer()
    #: Number of rows of elevation data.
    nrow: int | None = integer()


@node
class Skin(TypedElement):
    """A skinned mesh deformed by bones."""

    schema_keys: ClassVar[tuple[str, ...]] = ("asset/skin", "deformable/skin")
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Face vertex indices.
    face: Ints | None = integers()
    #: File name, relative to the model (or asset) directory.
    file: str | None = text()
    #: Integer group, used for visualization filters and by convention.
    group: int | None = integer()
    #: Distance by which skin vertices are pushed out along their normals.
    inflate: float | None = number()
    #: Name of the material asset used for rendering.
    material: str | None = text()
    #: Colour and transparency (r, g, b, a).
    rgba: Floats | None = vec4()
    #: Texture coordinates.
    texcoord: Floats | None = numbers()
    #: Vertex coordinates.
    vertex: Floats | None = numbers()


@node
class Bone(TypedElement):
    """A bone of a skin: a body and the vertices it moves."""

    schema_keys: ClassVar[tuple[str, ...]] = ("asset/skin/bone", "deformable/skin/bone")
    #: Bind position of the bone.
    bindpos: Floats | None = numbers()
    #: Bind orientation of the bone.
    bindquat: Floats | None = vec4()
    #: Name of the body.
    body: str | None = text()
    #: Indices of the skin vertices this bone moves.
    vertid: Ints | None = integers()
    #: Weights of the skin vertices this bone moves.
    vertweight: Floats | None = numbers()


@node
class Texture(TypedElement):
    """A texture asset, from files or built in."""

    schema_keys: ClassVar[tuple[str, ...]] = ("asset/texture", "default/texture")
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = text(xml="class")
    #: Element type keyword.
    type: str | None = text()
    #: Procedurally generated content.
    builtin: str | None = text()
    #: Colour space of the image.
    colorspace: str | None = text()
    #: MIME type of the file.
    content_type: str | None = text()
    #: Whether the image is embedded in compiled output.
    embed: str | None = text()
    #: File name, relative to the model (or asset) directory.
    file: str | None = text()
    #: File of the back face of a cube texture.
    fileback: str | None = text()
    #: File of the down face of a cube texture.
    filedown: str | None = text()
    #: File of the front face of a cube texture.
    filefront: str | None = text()
    #: File of the left face of a cube texture.
    fileleft: str | None = text()
    #: File of the right face of a cube texture.
    fileright: str | None = text()
    #: File of the up face of a cube texture.
    fileup: str | None = text()
    #: Layout of the faces in the grid.
    gridlayout: str | None = text()
    #: Grid size of a cube or skybox texture in one file.
    gridsize: Ints | None = integers()
    #: Height.
    height: int | None = integer()
    #: Whether to flip the image horizontally.
    hflip: bool | None = boolean()
    #: Marking of a built-in texture.
    mark: str | None = text()
    #: Colour of the marking.
    markrgb: Floats | None = vec3()
    #: Number of colour channels.
    nchannel: int | None = integer()
    #: Probability of random dots in a built-in texture.
    random: float | None = number()
    #: First colour of a built-in texture.
    rgb1: Floats | None = vec3()
    #: Second colour of a built-in texture.
    rgb2: Floats | None = vec3()
    #: Whether to flip the image vertically.
    vflip: bool | None = boolean()
    #: Width.
    width: int | None = integer()


@node
class Material(TypedElement):
    """A material asset."""

    schema_keys: ClassVar[tuple[str, ...]] = ("asset/material", "default/material")
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = text(xml="class")
    #: Emission, as a multiple of the colour.
    emission: float | None = number()
    #: Metallic value for physically based rendering.
    metallic: float | None = number()
    #: Reflectance.
    reflectance: float | None = number()
    #: Colour and transparency (r, g, b, a).
    rgba: Floats | None = vec4()
    #: Roughness value for physically based rendering.
    roughness: float | None = number()
    #: Shininess.
    shininess: float | None = number()
    #: Specular colour or intensity.
    specular: float | None = number()
    #: How many times the texture repeats.
    texrepeat: Floats | None = vec2()
    #: Name of the texture asset.
    texture: str | None = text()
    #: Whether texture repetition is in world units.
    texuniform: bool | None = boolean()


@node
class MaterialLayer(TypedElement):
    """A texture layer of a material."""

    schema_keys: ClassVar[tuple[str, ...]] = ("asset/material/layer", "default/material/layer")
    #: Role of the texture layer.
    role: str | None = text()
    #: Name of the texture asset.
    texture: str | None = text()


@node
class Model(TypedElement):
    """A model asset (another MJCF file) for ``<attach>``."""

    schema_keys: ClassVar[tuple[str, ...]] = ("asset/model",)
    #: Name, unique within its namespace.
    name: str | None = text()
    #: MIME type of the file.
    content_type: str | None = text()
    #: File name, relative to the model (or asset) directory.
    file: str | None = text()
