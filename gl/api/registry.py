"""The OpenGL registry (gl.xml, Debian's khronos-api) as the generator needs it: the commands,
enums and types of the configured features, with each command's C signature. Reads only;
it knows nothing of libshadelab-gl's tables (config.toml, pending.txt)."""

import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field


@dataclass
class Param:
    ctype: str  # as C spells it, without the name: "const GLfloat *"
    name: str
    length: str | None  # gl.xml's len attribute: "4", "n", "COMPSIZE(pname)", ...

    def declaration(self) -> str:
        sep = "" if self.ctype.endswith("*") else " "
        return f"{self.ctype}{sep}{self.name}"


@dataclass
class Command:
    name: str  # "glVertex3f"
    ret: str  # "void", "GLboolean", "const GLubyte *"
    params: list[Param]
    feature: str  # the configured feature that introduced it: "GL_VERSION_1_1"
    version: str  # that feature's number: "1.1"

    @property
    def short(self) -> str:
        """The name without "gl": the exec:: function's name."""
        return self.name[2:]

    def param_list(self, context: str | None = None) -> str:
        """The C parameter list; with `context`, a leading GlContext& of that name."""
        parts = [p.declaration() for p in self.params]
        if context is not None:
            parts.insert(0, f"GlContext& {context}")
        return ", ".join(parts) if parts else ("void" if context is None else "")

    def arg_list(self) -> str:
        return ", ".join(p.name for p in self.params)

    @property
    def returns(self) -> bool:
        return self.ret != "void"


@dataclass
class Extension:
    name: str  # "GL_ARB_multitexture"
    commands: list[str]  # its commands, suffixed: "glActiveTextureARB"


@dataclass
class Api:
    commands: list[Command]  # in the registry's feature order
    enums: list[tuple[str, str]]  # (name, value), feature order, then the extra enums
    typedefs: list[str]  # C typedef lines, in the registry's order
    features: list[tuple[str, str]] = field(default_factory=list)  # (name, number)
    aliases: dict[str, str] = field(default_factory=dict)  # extension command -> core command
    extensions: dict[str, Extension] = field(default_factory=dict)  # every gl extension, by name
    protos: dict[str, tuple[str, list[Param]]] = field(default_factory=dict)  # every command's signature

    def add_extension_commands(self, extension: str) -> list[Command]:
        """The commands of `extension` that alias no command of the features (its own, with
        signatures of their own: glVertexPointerEXT's count; or named after a later version's
        command, as glBlendEquationSeparateEXT), added to the API's commands with the
        extension's name as their feature and "ext" as their version."""
        added = []
        known = {c.name for c in self.commands}
        for name in self.extensions[extension].commands:
            # An alias of a command of the features is that command; an alias of a later
            # version's command (glBlendEquationSeparateEXT of GL 2.0's) is the extension's own.
            if name in known or self.aliases.get(name) in known:
                continue
            ret, params = self.protos[name]
            added.append(Command(name, ret, params, extension, "ext"))
        self.commands += added
        return added

    def command(self, name: str) -> Command:
        for c in self.commands:
            if c.name == name:
                return c
        raise KeyError(name)


def _text(element) -> str:
    return "".join(element.itertext())


def _split_declaration(element) -> tuple[str, str]:
    """(type, name) of a <proto> or <param>: the text before the name is the type."""
    name = element.find("name").text
    full = _text(element).strip()
    ctype = full[: full.rfind(name)].strip()
    ctype = re.sub(r"\s*\*", " *", ctype).replace("* *", "**")
    return ctype, name


def load(path: str, features: list[str], extra_enums: list[str], khronos: dict[str, str]) -> Api:
    root = ET.parse(path).getroot()
    by_feature: dict[str, tuple[str, list[str], list[str], list[str]]] = {}
    for f in root.findall("feature"):
        if f.get("api") != "gl" or f.get("name") not in features:
            continue
        cmds, enums, types = [], [], []
        for req in f.findall("require"):
            cmds += [c.get("name") for c in req.findall("command")]
            enums += [e.get("name") for e in req.findall("enum")]
            types += [t.get("name") for t in req.findall("type")]
        by_feature[f.get("name")] = (f.get("number"), cmds, enums, types)
    missing = [f for f in features if f not in by_feature]
    if missing:
        raise SystemExit(f"generate: {path}: no feature {', '.join(missing)}")

    protos = {}
    aliases = {}
    for c in root.find("commands").findall("command"):
        ret, name = _split_declaration(c.find("proto"))
        if c.find("alias") is not None:
            aliases[name] = c.find("alias").get("name")
        params = []
        for p in c.findall("param"):
            ctype, pname = _split_declaration(p)
            params.append(Param(ctype, pname, p.get("len")))
        protos[name] = (ret, params)

    values = {}
    for group in root.findall("enums"):
        for e in group.findall("enum"):
            if e.get("api") in (None, "gl"):
                values.setdefault(e.get("name"), e.get("value"))

    api = Api([], [], [])
    api.aliases = aliases
    api.protos = protos
    for x in root.find("extensions").findall("extension"):
        if "gl" not in (x.get("supported") or "").split("|"):
            continue
        cmds = [c.get("name") for req in x.findall("require") if req.get("api") in (None, "gl")
                for c in req.findall("command")]
        api.extensions[x.get("name")] = Extension(x.get("name"), cmds)
    wanted_types = set()
    for fname in features:
        number, cmds, enums, types = by_feature[fname]
        api.features.append((fname, number))
        for name in cmds:
            ret, params = protos[name]
            api.commands.append(Command(name, ret, params, fname, number))
        api.enums += [(e, values[e]) for e in enums]
        wanted_types.update(types)
    defined = {e for e, _ in api.enums}
    api.enums += [(e, values[e]) for e in extra_enums if e not in defined]

    used = set()
    for c in api.commands:
        for t in [c.ret] + [p.ctype for p in c.params]:
            used.update(re.findall(r"\bGL\w+", t))
    wanted_types |= used
    for t in root.find("types").findall("type"):
        name = t.get("name") or (t.find("name").text if t.find("name") is not None else None)
        if name not in wanted_types:
            continue
        line = _text(t).strip()
        for k, v in khronos.items():
            line = re.sub(rf"\b{k}\b", v, line)
        api.typedefs.append(line)
    return api
