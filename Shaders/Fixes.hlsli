// FIX_<Id> bit masks of the port's fixes (FixList.hlsli), to test against a
// constant buffer's g_Fixes: if (g_Fixes & FIX_UvInset) ...
#ifndef FIXES_HLSLI
#define FIXES_HLSLI
#define DRR_FIX(id, bit, name, help) static const uint FIX_##id = 1u << bit;
#include "FixList.hlsli"
#undef DRR_FIX
#endif
