from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.stiffness_design_out import StiffnessDesignOut
from ...models.stiffness_design_request import StiffnessDesignRequest
from ...types import Response


def _get_kwargs(
    *,
    body: StiffnessDesignRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/control/stiffness",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorOut | StiffnessDesignOut | None:
    if response.status_code == 200:
        response_200 = StiffnessDesignOut.from_dict(response.json())

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 413:
        response_413 = ErrorOut.from_dict(response.json())

        return response_413

    if response.status_code == 422:
        response_422 = ErrorOut.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorOut.from_dict(response.json())

        return response_503

    if response.status_code == 504:
        response_504 = ErrorOut.from_dict(response.json())

        return response_504

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Response[ErrorOut | StiffnessDesignOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: StiffnessDesignRequest,
) -> Response[ErrorOut | StiffnessDesignOut]:
    """Rest lengths for a stable pose with a shaped tip stiffness (variable stiffness)

     Rest lengths putting the tip at `target`, stable under the dead `load`, with the Cartesian tangent
    stiffness of the free tip (`K = (J H^-1 J^T)^-1`, as `/v1/stiffness`) equal to `K_desired` (the
    closest where it cannot be reached: `exact`, `residual`), or inside `bounds_K` (per entry) and
    `eig_bounds` (both eigenvalues) (`tensegrity_opt.preloads_for_stiffness`: IPOPT from the target's
    equilibria, `max_starts` shapes). Verified by the forward solve and `cartesian_stiffness`. Bounds
    that cannot be met: 422 `design_infeasible` with the least-violation point in `best`.

    Args:
        body (StiffnessDesignRequest): Rest lengths for a stable pose at `target` with a shaped
            tip stiffness (`preloads_for_stiffness`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | StiffnessDesignOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    body: StiffnessDesignRequest,
) -> ErrorOut | StiffnessDesignOut | None:
    """Rest lengths for a stable pose with a shaped tip stiffness (variable stiffness)

     Rest lengths putting the tip at `target`, stable under the dead `load`, with the Cartesian tangent
    stiffness of the free tip (`K = (J H^-1 J^T)^-1`, as `/v1/stiffness`) equal to `K_desired` (the
    closest where it cannot be reached: `exact`, `residual`), or inside `bounds_K` (per entry) and
    `eig_bounds` (both eigenvalues) (`tensegrity_opt.preloads_for_stiffness`: IPOPT from the target's
    equilibria, `max_starts` shapes). Verified by the forward solve and `cartesian_stiffness`. Bounds
    that cannot be met: 422 `design_infeasible` with the least-violation point in `best`.

    Args:
        body (StiffnessDesignRequest): Rest lengths for a stable pose at `target` with a shaped
            tip stiffness (`preloads_for_stiffness`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | StiffnessDesignOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: StiffnessDesignRequest,
) -> Response[ErrorOut | StiffnessDesignOut]:
    """Rest lengths for a stable pose with a shaped tip stiffness (variable stiffness)

     Rest lengths putting the tip at `target`, stable under the dead `load`, with the Cartesian tangent
    stiffness of the free tip (`K = (J H^-1 J^T)^-1`, as `/v1/stiffness`) equal to `K_desired` (the
    closest where it cannot be reached: `exact`, `residual`), or inside `bounds_K` (per entry) and
    `eig_bounds` (both eigenvalues) (`tensegrity_opt.preloads_for_stiffness`: IPOPT from the target's
    equilibria, `max_starts` shapes). Verified by the forward solve and `cartesian_stiffness`. Bounds
    that cannot be met: 422 `design_infeasible` with the least-violation point in `best`.

    Args:
        body (StiffnessDesignRequest): Rest lengths for a stable pose at `target` with a shaped
            tip stiffness (`preloads_for_stiffness`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | StiffnessDesignOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: StiffnessDesignRequest,
) -> ErrorOut | StiffnessDesignOut | None:
    """Rest lengths for a stable pose with a shaped tip stiffness (variable stiffness)

     Rest lengths putting the tip at `target`, stable under the dead `load`, with the Cartesian tangent
    stiffness of the free tip (`K = (J H^-1 J^T)^-1`, as `/v1/stiffness`) equal to `K_desired` (the
    closest where it cannot be reached: `exact`, `residual`), or inside `bounds_K` (per entry) and
    `eig_bounds` (both eigenvalues) (`tensegrity_opt.preloads_for_stiffness`: IPOPT from the target's
    equilibria, `max_starts` shapes). Verified by the forward solve and `cartesian_stiffness`. Bounds
    that cannot be met: 422 `design_infeasible` with the least-violation point in `best`.

    Args:
        body (StiffnessDesignRequest): Rest lengths for a stable pose at `target` with a shaped
            tip stiffness (`preloads_for_stiffness`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | StiffnessDesignOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
