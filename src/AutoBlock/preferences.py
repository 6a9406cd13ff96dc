"""AutoBlock's user preferences (Edit > Preferences > AutoBlock), with the core's defaults."""

import FreeCAD

GROUP = "User parameter:BaseApp/Preferences/Mod/AutoBlock"

# Parameter names; the preferences page (resources/ui/preferences.ui) uses the same ones.
DEFAULT_POLICY = "DefaultPolicy"
DEFAULT_POLICY_FILE = "DefaultPolicyFile"
REWARD_PRESET = "RewardPreset"
MESH_SIZE = "MeshSize"
THREADS = "Threads"
CAP_FACE = "CapFace"

# What Auto-Block does with a selected cap face of a sweepable solid (CAP_FACE), in the page's order.
CAP_FACE_CHOICES = ("solid", "face")


def params():
    return FreeCAD.ParamGet(GROUP)


def default_policy():
    """The policy to use when none is given: the preferred policy file, else the preferred name, else the
    core's default."""
    p = params()
    policy_file = p.GetString(DEFAULT_POLICY_FILE, "")
    if policy_file:
        return policy_file
    name = p.GetString(DEFAULT_POLICY, "")
    if name:
        return name
    from . import native

    return native.load().default_policy()


def reward_preset():
    """The preferred reward preset: "paper", "mesh", or "" (the core's default: each policy's own, so sac-mesh
    scores its cuts with the mesh preset and sac-paper and the baselines with the paper's Eq. (1))."""
    name = params().GetString(REWARD_PRESET, "")
    if name:
        return name
    from . import native

    return native.load().default_reward_preset()


def mesh_size():
    """Target element size of the quad mesh (model units); 0 means automatic."""
    return params().GetFloat(MESH_SIZE, 0.0)


def cap_face():
    """What Auto-Block makes of a selected cap face of a sweepable solid: "solid" (the default: the solid split into
    prism blocks and meshed with hexahedra, make_autoblock_solid) or "face" (the face alone, with quads)."""
    choice = params().GetString(CAP_FACE, "")
    return choice if choice in CAP_FACE_CHOICES else CAP_FACE_CHOICES[0]


def threads():
    """Threads for training (as stored: 0 means all cores). Decompositions with a learned policy use one
    thread, as the core decided (small networks run fastest that way)."""
    return params().GetInt(THREADS, 0)


def training_threads():
    """The number of threads training uses (threads(), with 0 resolved to the number of cores)."""
    import os

    return threads() or (os.cpu_count() or 1)


def set_default_policy(spec):
    """Make `spec` (a policy name or file) the default."""
    p = params()
    from . import native

    if spec in native.load().policy_names():
        p.SetString(DEFAULT_POLICY, spec)
        p.SetString(DEFAULT_POLICY_FILE, "")
    else:
        p.SetString(DEFAULT_POLICY_FILE, spec)
