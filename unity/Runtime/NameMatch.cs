// Importers decorate names: FBX bones may come as "mixamorig:left_hip" or
// "Armature|left_hip", blend shapes as "BlendShapeChannel.pose_left_hip_00"
// or "<mesh>.pose_left_hip_00". Match the exact name first, then a name that
// ends with the wanted one right after a separator (any character that is not
// a letter or digit), so "left_hip" never matches "upper_left_hipX" and
// "spine1" never matches "spine12".
using System;
using System.Collections.Generic;

namespace SmplExport.Correctives
{
    public static class NameMatch
    {
        /// <summary>True if candidate == wanted, or candidate ends with wanted after a separator.</summary>
        public static bool IsSuffixMatch(string candidate, string wanted)
        {
            if (candidate == null || string.IsNullOrEmpty(wanted) || candidate.Length <= wanted.Length) return false;
            if (!candidate.EndsWith(wanted, StringComparison.Ordinal)) return false;
            char before = candidate[candidate.Length - wanted.Length - 1];
            return !char.IsLetterOrDigit(before);
        }

        /// <summary>
        /// For each wanted name, the index of its candidate, or -1. Exact matches
        /// are assigned first and are never reused for another name's suffix
        /// match; among suffix matches the shortest candidate (least decorated)
        /// wins, the first one on ties.
        /// </summary>
        public static int[] Assign(IList<string> wanted, IList<string> candidates)
        {
            var result = new int[wanted.Count];
            var exactlyTaken = new HashSet<int>();
            var byName = new Dictionary<string, int>(StringComparer.Ordinal);
            for (int i = 0; i < candidates.Count; ++i)
                if (candidates[i] != null && !byName.ContainsKey(candidates[i])) byName[candidates[i]] = i;
            for (int w = 0; w < wanted.Count; ++w)
            {
                int index;
                result[w] = wanted[w] != null && byName.TryGetValue(wanted[w], out index) ? index : -1;
                if (result[w] >= 0) exactlyTaken.Add(result[w]);
            }
            for (int w = 0; w < wanted.Count; ++w)
            {
                if (result[w] >= 0) continue;
                for (int i = 0; i < candidates.Count; ++i)
                {
                    if (exactlyTaken.Contains(i) || !IsSuffixMatch(candidates[i], wanted[w])) continue;
                    if (result[w] < 0 || candidates[i].Length < candidates[result[w]].Length) result[w] = i;
                }
            }
            return result;
        }
    }
}
