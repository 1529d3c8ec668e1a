// Stand-in for the header Unreal Header Tool generates (nothing to generate here).
#pragma once
