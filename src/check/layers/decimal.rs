//! Products of state counts as exact decimal strings (counts of real designs pass 10^80).

/// A non-negative integer in base 10⁹ digits, least significant first.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BigCount(Vec<u32>);

const BASE: u128 = 1_000_000_000;

impl BigCount {
    /// The number one.
    pub fn one() -> BigCount {
        BigCount(vec![1])
    }

    /// Multiplies in place by `k`.
    pub fn mul(&mut self, k: u128) {
        if k == 0 {
            self.0 = vec![0];
            return;
        }
        let mut factor = Vec::new();
        let mut rest = k;
        while rest > 0 {
            factor.push((rest % BASE) as u32);
            rest /= BASE;
        }
        let mut out = vec![0u128; self.0.len() + factor.len() + 1];
        // Each slot sums fewer than 2^60 products below 10^18: no u128 overflow.
        for (i, &a) in self.0.iter().enumerate() {
            for (j, &b) in factor.iter().enumerate() {
                out[i + j] += u128::from(a) * u128::from(b);
            }
        }
        let mut carry = 0;
        for slot in &mut out {
            *slot += carry;
            carry = *slot / BASE;
            *slot %= BASE;
        }
        while out.len() > 1 && out.last() == Some(&0) {
            out.pop();
        }
        self.0 = out.into_iter().map(|d| d as u32).collect();
    }

    /// True when the value is zero.
    pub fn is_zero(&self) -> bool {
        self.0.iter().all(|&d| d == 0)
    }
}

impl std::fmt::Display for BigCount {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let mut digits = self.0.iter().rev();
        write!(f, "{}", digits.next().copied().unwrap_or(0))?;
        for d in digits {
            write!(f, "{d:09}")?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::BigCount;

    #[test]
    fn powers_of_two_match_u128_and_beyond() {
        let mut n = BigCount::one();
        for _ in 0..100 {
            n.mul(2);
        }
        // 2^100, computed independently as (2^50)^2 with u128 arithmetic
        assert_eq!(n.to_string(), ((1u128 << 50) * (1u128 << 50)).to_string());
        n.mul(1u128 << 100);
        assert_eq!(
            n.to_string(),
            "1606938044258990275541962092341162602522202993782792835301376"
        );
    }

    #[test]
    fn zero_absorbs() {
        let mut n = BigCount::one();
        n.mul(12345678901234567890);
        n.mul(0);
        assert!(n.is_zero());
        assert_eq!(n.to_string(), "0");
    }
}
